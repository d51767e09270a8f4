// Thermodynamic consistency of every EOS kernel, at compressed and expanded
// states (both branches for Mie-Grueneisen and polynomial):
// * the analytic sound speed equals the pressure slope along the isentrope,
//   de = (p/rho^2) drho, taken by central differences;
// * internal_energy(rho, pressure(rho, e)) gives e back.

#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>

#include "common/eos/any_eos.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::eos {
namespace {

using test_materials::kAir;
using test_materials::kSteel;
using test_materials::kTnt;
using test_materials::kWater;

struct State {
  std::string label;
  AnyEos eos;
  double rho;  // [kg/m^3]
  double e;    // [J/kg]
};

void PrintTo(const State& state, std::ostream* os) {
  *os << state.label;
}

std::string state_label(const ::testing::TestParamInfo<State>& info) {
  return info.param.label;
}

// Central differences with step h = 1e-5 rho: the error of the first-order
// isentrope step (e +- (p/rho^2) h) is even in h and cancels, so the slope is
// second-order, truncation ~ (h/rho)^2 (R1 V)^3 / 6 < 1e-8 relative even for
// JWL's steep exponentials; round-off ~ 1e-16 p / (h/rho rho c^2) < 1e-10.
// Hence a 1e-6 relative tolerance on c^2 fails only on a wrong derivative.
constexpr double kRelativeStep = 1e-5;
constexpr double kSoundSpeedTolerance = 1e-6;

double isentropic_pressure_slope(const AnyEos& eos, double rho, double e) {
  const double h = kRelativeStep * rho;
  const double de_drho = pressure(eos, rho, e) / (rho * rho);
  return (pressure(eos, rho + h, e + de_drho * h) - pressure(eos, rho - h, e - de_drho * h)) /
         (2.0 * h);
}

class EosAtState : public ::testing::TestWithParam<State> {};

TEST_P(EosAtState, AnalyticSoundSpeed_equals_isentropic_pressure_slope) {
  const State& s = GetParam();
  const double slope = isentropic_pressure_slope(s.eos, s.rho, s.e);
  ASSERT_GT(slope, 1e6 * kMinSoundSpeedSquared) << "state must be stable, away from the c^2 floor";
  const double c = sound_speed(s.eos, s.rho, s.e);
  EXPECT_NEAR(c * c, slope, kSoundSpeedTolerance * slope);
}

TEST_P(EosAtState, InternalEnergy_inverts_pressure_at_fixed_density) {
  const State& s = GetParam();
  const double p = pressure(s.eos, s.rho, s.e);
  const double p_ref = pressure(s.eos, s.rho, 0.0);
  const double dp_de = pressure(s.eos, s.rho, 1.0) - p_ref;  // exact: p is affine in e
  // e = (p - p_ref) / (dp/de) loses a few ulps of the largest term; 1e-12 of
  // that scale leaves margin for FMA contraction and still catches any slip.
  const double scale = std::abs(s.e) + (std::abs(p) + std::abs(p_ref)) / std::abs(dp_de);
  EXPECT_NEAR(internal_energy(s.eos, s.rho, p), s.e, 1e-12 * scale);
}

INSTANTIATE_TEST_SUITE_P(
    CompressedAndExpanded, EosAtState,
    ::testing::Values(State{"ideal_gas_ambient_air", kAir, 1.225, 2.0685e5},
                      State{"ideal_gas_shocked", kAir, 6.0, 1.0e6},
                      State{"ideal_gas_expanded", kAir, 0.05, 5.0e4},
                      State{"jwl_compressed_V0p75", kTnt, 1630.0 / 0.75, 4.5e6},
                      State{"jwl_initial_V1", kTnt, 1630.0, 6.993e9 / 1630.0},
                      State{"jwl_expanded_V3", kTnt, 1630.0 / 3.0, 2.5e6},
                      State{"jwl_expanded_V10", kTnt, 163.0, 1.0e6},
                      State{"mie_gruneisen_compressed_mu0p2", kSteel, 7890.0 * 1.2, 2.0e5},
                      State{"mie_gruneisen_compressed_mu0p05", kSteel, 7890.0 * 1.05, 0.0},
                      State{"mie_gruneisen_tension_mu_minus0p05", kSteel, 7890.0 * 0.95, 1.0e4},
                      State{"mie_gruneisen_tension_mu_minus0p1", kSteel, 7890.0 * 0.9, 3.0e5},
                      State{"polynomial_compressed_mu0p1", kWater, 1100.0, 1.0e5},
                      State{"polynomial_compressed_mu0p4", kWater, 1400.0, 1.0e6},
                      State{"polynomial_tension_mu_minus0p05", kWater, 950.0, 1.0e5},
                      State{"polynomial_tension_mu_minus0p1", kWater, 900.0, 0.0}),
    state_label);

}  // namespace
}  // namespace mpfd::eos
