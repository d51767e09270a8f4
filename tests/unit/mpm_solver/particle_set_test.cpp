#include "mpm_solver/particle_set.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

namespace mpfd::mpm {
namespace {

/// A set of n particles whose every value encodes its particle (and slot).
ParticleSet numbered(std::size_t n, std::size_t history_stride) {
  ParticleSet ps;
  ps.history_stride = history_stride;
  ps.grow(n);
  for (std::size_t p = 0; p < n; ++p) {
    int array = 0;
    ps.for_each_double_array([&](std::vector<double>& a, std::size_t stride) {
      for (std::size_t k = 0; k < stride; ++k)
        a[p * stride + k] = 1000.0 * static_cast<double>(p) + 10.0 * array + static_cast<double>(k);
      ++array;
    });
    ps.id[p] = 7 * p;
    ps.material[p] = static_cast<std::uint16_t>(p % 5);
    ps.body[p] = static_cast<std::uint16_t>(p % 3);
  }
  return ps;
}

/// Every array of `ps` holds, in order, the values of the particles in `kept`.
void expect_holds(ParticleSet& ps, const std::vector<std::size_t>& kept) {
  ASSERT_EQ(ps.size(), kept.size());
  int array = 0;
  ps.for_each_double_array([&](std::vector<double>& a, std::size_t stride) {
    ASSERT_EQ(a.size(), kept.size() * stride);
    for (std::size_t i = 0; i < kept.size(); ++i)
      for (std::size_t k = 0; k < stride; ++k)
        ASSERT_EQ(a[i * stride + k],
                  1000.0 * static_cast<double>(kept[i]) + 10.0 * array + static_cast<double>(k))
            << "array " << array << ", entry " << i;
    ++array;
  });
  for (std::size_t i = 0; i < kept.size(); ++i) {
    EXPECT_EQ(ps.id[i], 7 * kept[i]);
    EXPECT_EQ(ps.material[i], kept[i] % 5);
    EXPECT_EQ(ps.body[i], kept[i] % 3);
  }
}

/// The particles the slots hold after removal: each removed slot below the new
/// size takes the next kept particle from above it.
std::vector<std::size_t> expected_after(const std::vector<std::uint8_t>& flags) {
  std::size_t kept = 0;
  for (const auto f : flags) kept += f == 0 ? 1 : 0;
  std::vector<std::size_t> slots;
  std::size_t filler = kept;
  for (std::size_t p = 0; p < kept; ++p) {
    if (flags[p] == 0) {
      slots.push_back(p);
      continue;
    }
    while (flags[filler] != 0) ++filler;
    slots.push_back(filler++);
  }
  return slots;
}

TEST(ParticleSetRemoval, KeepsEveryUnflaggedParticleWholeInEveryArray) {
  std::mt19937 random(11);
  for (const double share : {0.0, 0.01, 0.3, 0.9, 1.0}) {
    const std::size_t n = 257;
    ParticleSet ps = numbered(n, 3);
    std::vector<std::uint8_t> flags(n, 0);
    std::bernoulli_distribution flagged(share);
    for (auto& f : flags) f = flagged(random) ? 2 : 0;  // any nonzero value flags
    if (share > 0.0 && share < 1.0) {
      flags.front() = 1;  // runs that touch both ends
      flags.back() = 1;
    }
    const std::vector<std::size_t> kept = expected_after(flags);
    std::vector<std::size_t> sorted = kept;
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::size_t> unflagged;
    for (std::size_t p = 0; p < n; ++p)
      if (flags[p] == 0) unflagged.push_back(p);
    EXPECT_EQ(sorted, unflagged);  // the rule above keeps exactly the unflagged ones
    for (std::size_t i = 0; i < kept.size(); ++i) EXPECT_LE(i, kept[i]);  // never moves up
    EXPECT_EQ(ps.remove_flagged(flags), n - kept.size()) << "share " << share;
    expect_holds(ps, kept);
  }
}

TEST(ParticleSetRemoval, TheLastParticleLeavesTheOthersInPlace) {
  ParticleSet ps = numbered(5, 2);
  EXPECT_EQ(ps.remove_flagged(std::vector<std::uint8_t>{0, 0, 0, 0, 1}), 1u);
  expect_holds(ps, {0, 1, 2, 3});
}

TEST(ParticleSetRemoval, AnEarlySlotTakesTheLastKeptParticle) {
  ParticleSet ps = numbered(6, 2);
  EXPECT_EQ(ps.remove_flagged(std::vector<std::uint8_t>{0, 1, 0, 0, 0, 1}), 2u);
  expect_holds(ps, {0, 4, 2, 3});
}

}  // namespace
}  // namespace mpfd::mpm
