// Closed-form values at reference states: the ideal gas of the seed's air,
// zero pressure of the solids at their reference state, continuity of the
// polynomial EOS across mu = 0, and the c^2 floor.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/eos/any_eos.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::eos {
namespace {

using test_materials::kAir;
using test_materials::kAirDensity;
using test_materials::kAirEnergy;
using test_materials::kSteel;
using test_materials::kTnt;
using test_materials::kWater;

TEST(IdealGas, Seed_air_is_at_one_atmosphere_with_340_m_per_s_sound_speed) {
  // (1.4 - 1) * 1.225 * 2.0685e5 = 101356.5 Pa, c = sqrt(1.4 p / rho).
  EXPECT_DOUBLE_EQ(kAir.pressure(kAirDensity, kAirEnergy), 101356.5);
  EXPECT_DOUBLE_EQ(kAir.sound_speed(kAirDensity, kAirEnergy), std::sqrt(1.4 * 101356.5 / 1.225));
  EXPECT_NEAR(kAir.sound_speed(kAirDensity, kAirEnergy), 340.35, 0.01);
  EXPECT_DOUBLE_EQ(kAir.internal_energy(kAirDensity, 101356.5), kAirEnergy);
}

TEST(IdealGas, Pressure_is_linear_in_density_and_energy) {
  const IdealGas monatomic{.gamma = 5.0 / 3.0};
  EXPECT_DOUBLE_EQ(monatomic.pressure(2.0, 3.0), 4.0);
  EXPECT_DOUBLE_EQ(monatomic.pressure(4.0, 3.0), 8.0);
  EXPECT_DOUBLE_EQ(monatomic.pressure(2.0, 6.0), 8.0);
  EXPECT_DOUBLE_EQ(monatomic.sound_speed(2.0, 9.0), std::sqrt(10.0));  // 5/3 * 2/3 * 9
}

TEST(MieGruneisen, Pressure_vanishes_at_reference_density_and_zero_energy) {
  EXPECT_EQ(kSteel.pressure(kSteel.rho0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(kSteel.sound_speed(kSteel.rho0, 0.0), kSteel.c0);  // c^2 = pH'(0)/rho0 = C0^2
  EXPECT_EQ(kSteel.internal_energy(kSteel.rho0, 0.0), 0.0);
}

TEST(Polynomial, Pressure_vanishes_at_reference_density_and_zero_energy) {
  EXPECT_EQ(kWater.pressure(kWater.rho0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(kWater.sound_speed(kWater.rho0, 0.0), std::sqrt(kWater.t1 / kWater.rho0));
  EXPECT_EQ(kWater.internal_energy(kWater.rho0, 0.0), 0.0);
}

TEST(Polynomial, Pressure_is_continuous_across_mu_zero) {
  // Both branches give B0 rho0 e at mu = 0; one step of 1e-9 in mu on each
  // side moves p by about A1 1e-9 = 2.2 Pa plus the B1 term, never by a jump.
  constexpr double kStep = 1e-9;
  for (const double e : {0.0, 1.0e5, 1.0e6}) {
    const double at_zero = kWater.pressure(kWater.rho0, e);
    EXPECT_DOUBLE_EQ(at_zero, kWater.b0 * kWater.rho0 * e);
    const double above = kWater.pressure(kWater.rho0 * (1.0 + kStep), e);
    const double below = kWater.pressure(kWater.rho0 * (1.0 - kStep), e);
    const double bound = 2.0 * (kWater.a1 + kWater.t1 + kWater.b1 * kWater.rho0 * e) * kStep;
    EXPECT_NEAR(above, at_zero, bound) << "e = " << e;
    EXPECT_NEAR(below, at_zero, bound) << "e = " << e;
  }
}

TEST(MieGruneisen, Hugoniot_branches_agree_at_mu_zero_in_value_and_slope) {
  const ValueAndSlope compressed = kSteel.hugoniot_pressure(1e-12);
  const ValueAndSlope tension = kSteel.hugoniot_pressure(-1e-12);
  const double k = kSteel.rho0 * kSteel.c0 * kSteel.c0;
  EXPECT_NEAR(compressed.value, -tension.value, 1e-9 * std::abs(tension.value));
  EXPECT_NEAR(compressed.slope, tension.slope, 1e-10 * k);
}

TEST(SoundSpeedFloor, Unstable_states_get_the_floor_and_NaN_stays_NaN) {
  const double floor = std::sqrt(kMinSoundSpeedSquared);
  EXPECT_EQ(kAir.sound_speed(1.0, -1.0e5), floor);  // e < 0: c^2 < 0
  EXPECT_EQ(kAir.sound_speed(1.0, 0.0), floor);     // cold gas: c^2 = 0
  // Water stretched to mu = -0.5 with strongly negative energy: c^2 < 0.
  EXPECT_EQ(kWater.sound_speed(500.0, -1.0e7), floor);
  EXPECT_TRUE(std::isnan(kTnt.sound_speed(1630.0, std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
}  // namespace mpfd::eos
