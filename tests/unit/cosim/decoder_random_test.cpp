// Randomized decoder test: thousands of random, truncated and bit-flipped
// buffers must each decode or throw mpfd::Error, never crash (deterministic seed).

#include <gtest/gtest.h>

#include <random>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/codec.hpp"

namespace mpfd::cosim {
namespace {

std::vector<std::vector<std::byte>> valid_parts() {
  Message message;
  message.header.mutable_envelope()->set_protocol_major(protocol_major);
  message.header.mutable_envelope()->set_sender("fdm");
  message.header.mutable_envelope()->set_run_id("run-42");
  auto* results = message.header.mutable_exchange_result();
  results->add_results()->mutable_exported()->set_region("strip");
  results->add_results()->mutable_proposed()->set_stable_dt(1e-7);
  const std::vector<double> rho(16, 1.2);
  const std::vector<std::uint64_t> ids(5, 7);
  add_array(message, {"strip", "rho", {}, "kg/m^3"}, std::span<const double>(rho));
  add_array(message, {"strip", "id", {}, "1"}, std::span<const std::uint64_t>(ids));
  std::vector<std::vector<std::byte>> parts;
  for (auto& part : encode(std::move(message))) {
    const auto* bytes = static_cast<const std::byte*>(part.data());
    parts.emplace_back(bytes, bytes + part.size());
  }
  return parts;
}

/// Decodes; returns true on success, false on mpfd::Error. Anything else fails the test.
bool decodes(const std::vector<std::vector<std::byte>>& parts) {
  std::vector<std::span<const std::byte>> views(parts.begin(), parts.end());
  try {
    decode_bytes(views);
    return true;
  } catch (const Error& error) {
    EXPECT_GT(std::string(error.what()).size(), 10U);
    return false;
  }
}

TEST(DecoderRandomized, ValidMessageDecodes) {
  EXPECT_TRUE(decodes(valid_parts()));
}

TEST(DecoderRandomized, RandomBytesAreRejectedWithoutCrashing) {
  std::mt19937_64 random(20240601);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_int_distribution<std::size_t> length(0, 300);
  std::uniform_int_distribution<std::size_t> part_count(0, 4);
  int accepted = 0;
  for (int trial = 0; trial < 5000; ++trial) {
    std::vector<std::vector<std::byte>> parts(part_count(random));
    for (auto& part : parts) {
      part.resize(length(random));
      for (auto& b : part) b = static_cast<std::byte>(byte(random));
    }
    accepted += decodes(parts) ? 1 : 0;
  }
  EXPECT_LT(accepted, 50);  // random bytes almost never form a valid v1 header with a body
}

TEST(DecoderRandomized, TruncatedHeadersAndFramesAreRejected) {
  const auto valid = valid_parts();
  for (std::size_t part = 0; part < valid.size(); ++part) {
    for (std::size_t keep = 0; keep < valid[part].size(); ++keep) {
      auto parts = valid;
      parts[part].resize(keep);
      if (part > 0) {
        EXPECT_FALSE(decodes(parts)) << "frame " << part << " cut to " << keep;
      } else {
        decodes(parts);
      }
    }
  }
  auto missing = valid;
  missing.pop_back();
  EXPECT_FALSE(decodes(missing));
}

TEST(DecoderRandomized, BitFlippedHeadersDecodeOrAreRejected) {
  const auto valid = valid_parts();
  std::mt19937_64 random(7);
  for (int trial = 0; trial < 5000; ++trial) {
    auto parts = valid;
    auto& header = parts.front();
    const int flips = 1 + trial % 4;
    for (int f = 0; f < flips; ++f) {
      const std::size_t bit = random() % (header.size() * 8);
      header[bit / 8] ^= static_cast<std::byte>(1U << (bit % 8));
    }
    decodes(parts);
  }
}

}  // namespace
}  // namespace mpfd::cosim
