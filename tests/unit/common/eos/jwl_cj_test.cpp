// The Chapman-Jouguet state of TNT (T Table 3.1) and the CJ conditions: the
// Rayleigh line is tangent to the products' Hugoniot, and the flow behind the
// front is sonic (D - u = c).

#include "common/eos/jwl_cj.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "common/core/error.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::eos {
namespace {

using test_materials::kTnt;

/// The products' Hugoniot pressure at relative volume v, found here from the
/// pressure kernel alone: p solves e(rho, p) = e0 + p (1 - V) / (2 rho0), and
/// both sides are affine in p, so two evaluations fix it.
double hugoniot_from_kernel(const Jwl& eos, double v) {
  const double rho = eos.rho0 / v;
  const double e0 = eos.detonation_energy / eos.rho0;
  const auto residual = [&](double p) {
    return eos.internal_energy(rho, p) - e0 - p * (1.0 - v) / (2.0 * eos.rho0);
  };
  constexpr double kProbe = 1e10;  // [Pa], of the order of the answer
  const double r0 = residual(0.0);
  return -r0 * kProbe / (residual(kProbe) - r0);
}

TEST(JwlChapmanJouguet, Tnt_pressure_and_detonation_velocity_match_the_literature) {
  // T Table 3.1 / METHOD §3: p_CJ = 20.99 GPa (the JWL fit's CJ point) and
  // D = 6930 m/s; 0.5 % is the spread of the published fits.
  const ChapmanJouguetState cj = chapman_jouguet_state(kTnt);
  EXPECT_NEAR(cj.pressure, 20.99e9, 0.005 * 20.99e9);
  EXPECT_NEAR(cj.detonation_velocity, 6928.0, 0.005 * 6928.0);
  EXPECT_GT(cj.density, kTnt.rho0);
  EXPECT_DOUBLE_EQ(cj.particle_velocity,
                   cj.detonation_velocity * (1.0 - kTnt.rho0 / cj.density));  // mass flux
}

TEST(JwlChapmanJouguet, Rayleigh_line_is_tangent_to_the_products_hugoniot) {
  const ChapmanJouguetState cj = chapman_jouguet_state(kTnt);
  const double v = kTnt.rho0 / cj.density;
  // On the Hugoniot, by the kernel-only construction (round-off of the affine solve).
  EXPECT_NEAR(hugoniot_from_kernel(kTnt, v), cj.pressure, 1e-9 * cj.pressure);
  // Rayleigh line p = rho0 D^2 (1 - V): slope -rho0 D^2 in the (V, p) plane.
  const double rayleigh_slope = -kTnt.rho0 * cj.detonation_velocity * cj.detonation_velocity;
  EXPECT_NEAR(rayleigh_slope, -cj.pressure / (1.0 - v), 1e-12 * cj.pressure / (1.0 - v));
  // Hugoniot slope by central differences, h = 1e-5: truncation ~ h^2 p''' / p'
  // ~ 1e-9, round-off ~ 1e-16 p / (h p') ~ 1e-11, so 1e-6 catches a point
  // off the tangency by more than ~1e-6 in V.
  constexpr double kStep = 1e-5;
  const double hugoniot_slope =
      (hugoniot_from_kernel(kTnt, v + kStep) - hugoniot_from_kernel(kTnt, v - kStep)) /
      (2.0 * kStep);
  EXPECT_NEAR(hugoniot_slope, rayleigh_slope, 1e-6 * std::abs(rayleigh_slope));
  // The library's analytic Hugoniot slope agrees too.
  EXPECT_NEAR(products_hugoniot(kTnt, v).slope, rayleigh_slope, 1e-9 * std::abs(rayleigh_slope));
}

TEST(JwlChapmanJouguet, Cj_point_is_the_least_rayleigh_slope_on_the_hugoniot) {
  const ChapmanJouguetState cj = chapman_jouguet_state(kTnt);
  const double v_cj = kTnt.rho0 / cj.density;
  const double least = cj.pressure / (1.0 - v_cj);
  for (double v = 0.2; v < 0.99; v += 0.01) {
    EXPECT_GE(hugoniot_from_kernel(kTnt, v) / (1.0 - v), least * (1.0 - 1e-12)) << "V = " << v;
  }
}

TEST(JwlChapmanJouguet, Flow_behind_the_front_is_sonic) {
  // CJ condition: D = u + c at the CJ state, c from the JWL sound-speed kernel
  // at e_CJ = e0 + p (v0 - v) / 2 (Hugoniot). Independent of the tangency
  // solve, so it checks the kernel's c^2 and the CJ point together.
  const ChapmanJouguetState cj = chapman_jouguet_state(kTnt);
  const double v = kTnt.rho0 / cj.density;
  const double e_cj = (kTnt.detonation_energy + cj.pressure * (1.0 - v) / 2.0) / kTnt.rho0;
  const double c = kTnt.sound_speed(cj.density, e_cj);
  EXPECT_NEAR(cj.detonation_velocity - cj.particle_velocity, c, 1e-9 * c);
}

TEST(JwlChapmanJouguet, Invalid_parameters_are_reported_before_solving) {
  Jwl bad = kTnt;
  bad.omega = 1.5;
  EXPECT_THAT([&] { (void)chapman_jouguet_state(bad); },
              ::testing::ThrowsMessage<Error>(
                  ::testing::HasSubstr("jwl: omega must be in (0, 1), got 1.5")));
}

}  // namespace
}  // namespace mpfd::eos
