// Check (2): a gas sphere at 10 times the ambient pressure expanding into gas.
// Mass is carried by particles (exact); total energy, kinetic + internal, is
// conserved up to the time-integration error, q included (it enters the
// energy equation (2-4) as it enters the stress). The totals include the
// ambient gas's internal energy (1.04 MJ of 1.12 MJ): the -1.2e-3 measured at
// CFL 0.5 is 1.3 kJ, 1.6 % of the 84 kJ internal energy of the hot sphere.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm_solver/spherical/spherical_mpm.hpp"

namespace mpfd::mpm::spherical {
namespace {

struct Budget {
  double mass_change;
  double energy_change;
  double kinetic_fraction;
};

Budget expand_gas_sphere(RadialShape shape, double cfl) {
  config::Material air;
  air.name = "air";
  air.eos = eos::IdealGas{1.4};
  SphericalOptions o;
  o.grid_spacing = 0.01;
  o.shape = shape;
  o.cfl = cfl;
  o.outer_boundary = OuterBoundary::free;  // no work crosses it; the shock stays inside
  o.margin_cells = 200;                    // room for the 1 bar surface expanding into vacuum
  SphericalMpm mpm({{air, 0.2, 1.0, 2.5e6, false}, {air, 1.0, 1.0, 2.5e5, false}}, o);
  const SphericalTotals before = mpm.totals();
  while (mpm.time() < 3e-4) mpm.advance(mpm.stable_dt());
  const SphericalTotals after = mpm.totals();
  const double e0 = before.kinetic_energy + before.internal_energy;
  return {after.mass / before.mass - 1.0, (after.kinetic_energy + after.internal_energy) / e0 - 1.0,
          after.kinetic_energy / e0};
}

TEST(GasSphereExpansion, MassIsExactAndEnergyWithinTwoTenthsOfAPercentWithGimp) {
  const Budget b = expand_gas_sphere(RadialShape::gimp, 0.5);
  EXPECT_EQ(b.mass_change, 0.0);
  EXPECT_LT(std::abs(b.energy_change), 2e-3) << "measured -1.2e-3 at CFL 0.5";
  EXPECT_GT(b.kinetic_fraction, 0.05) << "the gas must actually expand";
}

TEST(GasSphereExpansion, EnergyErrorShrinksWithTheTimeStep) {
  const Budget coarse = expand_gas_sphere(RadialShape::gimp, 0.5);
  const Budget fine = expand_gas_sphere(RadialShape::gimp, 0.1);
  EXPECT_LT(std::abs(fine.energy_change), 0.4 * std::abs(coarse.energy_change));
}

TEST(GasSphereExpansion, LinearShapesConserveEnergyWithinOnePercent) {
  const Budget b = expand_gas_sphere(RadialShape::linear, 0.5);
  EXPECT_EQ(b.mass_change, 0.0);
  EXPECT_LT(std::abs(b.energy_change), 1e-2) << "measured -6.4e-3 at CFL 0.5";
}

}  // namespace
}  // namespace mpfd::mpm::spherical
