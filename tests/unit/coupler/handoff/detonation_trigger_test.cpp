#include "coupler/handoff/detonation_trigger.hpp"

#include <gtest/gtest.h>

#include <array>

#include "common/core/error.hpp"

namespace mpfd::coupler::handoff {
namespace {

constexpr double kD = 6930.0;  // TNT detonation velocity [m/s], T Table 3.1
constexpr double kH = 1e-3;    // characteristic length [m]

TEST(ReactionFraction, Ramps_over_one_and_a_half_cells_of_detonation_travel_T_3_2) {
  const double t_l = 1e-5;
  EXPECT_EQ(reaction_fraction(0.9e-5, t_l, kD, kH), 0.0);
  const double half = 0.75 * kH / kD;  // F = 1/2
  EXPECT_NEAR(reaction_fraction(t_l + half, t_l, kD, kH), 0.5, 1e-12);
  EXPECT_EQ(reaction_fraction(t_l + 4.0 * half, t_l, kD, kH), 1.0);  // capped
}

TEST(ReactionFraction, Non_positive_detonation_velocity_is_an_error) {
  EXPECT_THROW((void)reaction_fraction(1.0, 0.0, 0.0, kH), Error);
}

TEST(DetonationComplete, Fires_only_when_every_explosive_particle_has_F_at_least_one) {
  const std::array<int, 4> material{0, 2, 0, 1};  // 0 = air, 1 and 2 explosives
  const std::array<int, 2> explosives{1, 2};
  std::array<double, 4> f{0.0, 1.0, 0.3, 0.999};
  EXPECT_FALSE(detonation_complete(f, material, explosives));
  f[3] = 1.0;
  EXPECT_TRUE(detonation_complete(f, material, explosives));  // air's F does not matter
}

TEST(DetonationComplete, Size_mismatch_is_an_error) {
  const std::array<int, 2> material{1, 1};
  const std::array<double, 1> f{1.0};
  const std::array<int, 1> explosives{1};
  EXPECT_THROW((void)detonation_complete(f, material, explosives), Error);
}

}  // namespace
}  // namespace mpfd::coupler::handoff
