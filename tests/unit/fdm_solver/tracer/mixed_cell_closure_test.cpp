// Mixed-cell closure, T (3-24)-(3-28), and the energy split of T §3.3.

#include "fdm_solver/tracer/mixed_cell_closure.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "fdm_solver/tracer/energy_split.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::fdm {
namespace {

namespace tm = eos::test_materials;

// The brief's acceptance tolerance for (3-24) and (3-28); the solver stops at 1e-12.
constexpr double kClosureTol = 1e-10;

const eos::AnyEos kAir = tm::kAir;
const eos::AnyEos kGamma3 = eos::IdealGas{.gamma = 3.0};
const eos::AnyEos kTnt = tm::kTnt;

void expect_equilibrium(const eos::AnyEos& eos1, const eos::AnyEos& eos2, const MixedCellInput& in,
                        const MixedCellState& s) {
  ASSERT_EQ(s.status, ClosureStatus::converged);
  const double p1 = eos::pressure(eos1, s.rho1, s.e1);
  const double p2 = eos::pressure(eos2, s.rho2, s.e2);
  EXPECT_NEAR(p1, p2, kClosureTol * std::max(std::abs(p1), std::abs(p2)));  // T (3-24)
  EXPECT_NEAR(in.theta1 * s.rho1 + (1.0 - in.theta1) * s.rho2, in.rho_c,    // T (3-28)
              kClosureTol * in.rho_c);
  EXPECT_NEAR(s.pressure, p1, kClosureTol * std::abs(p1));
}

TEST(MixedCellClosure, TwoIdealGasesSatisfyEq324AndEq328AndTheAnalyticDensities) {
  for (const double rho_c : {0.5, 1.225, 40.0})
    for (const double theta1 : {1e-6, 0.2, 0.5, 0.9, 1.0 - 1e-6})
      for (const double e2 : {1e4, 2.0685e5, 5e6}) {
        const MixedCellInput in{.rho_c = rho_c,
                                .theta1 = theta1,
                                .e1 = 2.0685e5,
                                .e2 = e2,
                                .cell_energy = std::nullopt};
        const MixedCellState s = close_mixed_cell(kAir, kGamma3, in);
        expect_equilibrium(kAir, kGamma3, in, s);
        // (g1 - 1) rho1 e1 = (g2 - 1) rho2 e2 with (3-28): rho1 = b rho_c / (a theta2 + b theta1)
        const double a = 0.4 * in.e1;
        const double b = 2.0 * e2;
        EXPECT_NEAR(s.rho1, b * rho_c / (a * (1.0 - theta1) + b * theta1), kClosureTol * s.rho1);
        EXPECT_EQ(s.e1, in.e1);  // no cell_energy: energies untouched
      }
}

TEST(MixedCellClosure, JwlProductsAgainstAirAtTypicalStates) {
  struct Case {
    double rho_c, theta_products, e_products, e_air;
  };
  // Early (products near rho0, shocked air), intermediate, and late expansion.
  for (const Case& c : {Case{900.0, 0.5, 4.29e6, 2.0e6}, Case{50.0, 0.3, 3.0e6, 1.0e6},
                        Case{5.0, 0.6, 2.0e6, 5.0e5}, Case{1.3, 0.1, 1.5e6, 2.0685e5}}) {
    const MixedCellInput in{.rho_c = c.rho_c,
                            .theta1 = c.theta_products,
                            .e1 = c.e_products,
                            .e2 = c.e_air,
                            .cell_energy = std::nullopt};
    const MixedCellState s = close_mixed_cell(kTnt, kAir, in);
    expect_equilibrium(kTnt, kAir, in, s);
    EXPECT_GT(s.pressure, 0.0);
  }
}

TEST(MixedCellClosure, CellEnergyIsConservedByACommonFactorOnTheSplitEnergies) {
  const MixedCellInput in{
      .rho_c = 60.0, .theta1 = 0.4, .e1 = 3.0e6, .e2 = 6.0e5, .cell_energy = 1.2e6};
  const MixedCellState s = close_mixed_cell(kTnt, kAir, in);
  expect_equilibrium(kTnt, kAir, in, s);
  const double y1 = in.theta1 * s.rho1 / in.rho_c;
  EXPECT_NEAR(y1 * s.e1 + (1.0 - y1) * s.e2, *in.cell_energy, 1e-12 * *in.cell_energy);
  EXPECT_NEAR(s.e1 / s.e2, in.e1 / in.e2, 1e-12 * in.e1 / in.e2);  // the split's ratio kept
}

TEST(MixedCellClosure, WithoutARootTakesTheDocumentedFallbackAndFlagsIt) {
  // Material 2 at e < 0 has p2 < 0 at every density, material 1 p1 >= 0: no equilibrium.
  const MixedCellInput in{
      .rho_c = 1.2, .theta1 = 0.3, .e1 = 2.0e5, .e2 = -1.0e4, .cell_energy = std::nullopt};
  const MixedCellState s = close_mixed_cell(kAir, kAir, in);
  EXPECT_EQ(s.status, ClosureStatus::fallback);
  EXPECT_EQ(s.rho1, in.rho_c);
  EXPECT_EQ(s.rho2, in.rho_c);
  EXPECT_NEAR(s.pressure, 0.3 * 0.4 * 1.2 * 2.0e5 + 0.7 * 0.4 * 1.2 * -1.0e4, 1e-12 * 3e4);
}

TEST(MixedCellClosure, NonFiniteInputIsFlaggedNotSolved) {
  const MixedCellInput in{
      .rho_c = 1.2, .theta1 = 0.3, .e1 = std::nan(""), .e2 = 2.0e5, .cell_energy = std::nullopt};
  EXPECT_EQ(close_mixed_cell(kAir, kTnt, in).status, ClosureStatus::fallback);
}

TEST(MixedCellClosure, NeverNaNFor10000RandomPhysicalInputs) {
  std::mt19937_64 rng(20140601);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto log_uniform = [&](double lo, double hi) { return lo * std::pow(hi / lo, unit(rng)); };
  int fallbacks = 0;
  for (int n = 0; n < 10000; ++n) {
    MixedCellInput in{.rho_c = log_uniform(0.1, 2000.0),
                      .theta1 = 1e-4 + (1.0 - 2e-4) * unit(rng),
                      .e1 = log_uniform(1e5, 1e7),
                      .e2 = log_uniform(1e4, 1e7),
                      .cell_energy = std::nullopt};
    if (n % 2 == 1) in.cell_energy = log_uniform(1e4, 1e7);
    const MixedCellState s = close_mixed_cell(kTnt, kAir, in);
    const bool finite = std::isfinite(s.rho1) && std::isfinite(s.rho2) && std::isfinite(s.e1) &&
                        std::isfinite(s.e2) && std::isfinite(s.pressure);
    ASSERT_TRUE(finite) << "input " << n << ": rho_c " << in.rho_c << " theta1 " << in.theta1;
    EXPECT_GE(std::min(s.rho1, s.rho2), 0.0);
    fallbacks += s.status == ClosureStatus::fallback ? 1 : 0;
    if (s.status == ClosureStatus::converged) {
      const double p1 = eos::pressure(kTnt, s.rho1, s.e1);
      const double p2 = eos::pressure(kAir, s.rho2, s.e2);
      EXPECT_NEAR(p1, p2, kClosureTol * std::max(std::abs(p1), std::abs(p2))) << "input " << n;
    }
  }
  EXPECT_EQ(fallbacks, 0);  // physical states always have an equilibrium here
}

// Doc and code must not drift: T §3.3 assumption (2) and the common factor of
// energy_split.hpp, written out again.
TEST(EnergySplit, FollowsTheDocumentedFormulas) {
  EXPECT_DOUBLE_EQ(split_energy_increment(2.0e5, 0.3, 1.0e4), 2.0e5 + 0.3 * 1.0e4);
  const double s = energy_scale(0.2, 0.8, {3.0e6, 5.0e5}, 1.0e6);
  EXPECT_NEAR(0.2 * s * 3.0e6 + 0.8 * s * 5.0e5, 1.0e6, 1e-12 * 1.0e6);
  const EnergyPair reset = energies_to_rescale({-1.0, 5.0e5}, 7.0e5);
  EXPECT_EQ(reset.first, 7.0e5);
  EXPECT_EQ(reset.second, 7.0e5);
}

}  // namespace
}  // namespace mpfd::fdm
