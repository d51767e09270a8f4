// Seeding (S eq. (1)), setup errors, and V-style check (3): a uniform gas at
// rest stays at rest, with no spurious force at r = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "common/core/error.hpp"
#include "mpm_solver/spherical/spherical_mpm.hpp"
#include "underwater_case.hpp"

namespace mpfd::mpm::spherical {
namespace {

config::Material air() {
  config::Material m;
  m.name = "air";
  m.eos = eos::IdealGas{1.4};
  return m;
}

SphericalOptions options(RadialShape shape, OuterBoundary boundary) {
  SphericalOptions o;
  o.grid_spacing = 0.01;
  o.shape = shape;
  o.outer_boundary = boundary;
  return o;
}

class BothShapes : public ::testing::TestWithParam<RadialShape> {};

TEST_P(BothShapes, TotalMassIsTheLayersShellMassesToRoundOff) {
  const SphericalMpm mpm(testing::underwater_layers(1.0), options(GetParam(), OuterBoundary::free));
  const double a = testing::kChargeRadius;
  const double exact = 4.0 * std::numbers::pi / 3.0 *
                       (testing::kTntDensity * a * a * a + 1000.0 * (1.0 - a * a * a));
  EXPECT_NEAR(mpm.totals().mass / exact, 1.0, 1e-13);
  EXPECT_EQ(mpm.particles().size(), 200U);
}

TEST_P(BothShapes, UnburntExplosiveStartsWithoutPressure) {
  const SphericalMpm mpm(testing::underwater_layers(0.5), options(GetParam(), OuterBoundary::free));
  EXPECT_EQ(mpm.particles().pressure.front(), 0.0);
  EXPECT_EQ(mpm.particles().burn_fraction.front(), 0.0);
  EXPECT_NEAR(mpm.particles().specific_internal_energy.front(), 6.993e9 / 1630.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(Spherical, BothShapes,
                         ::testing::Values(RadialShape::linear, RadialShape::gimp));

// GIMP with the transmitting boundary holding p = 1 bar: the whole sphere
// stays at rest. 1000 steps = 13 ms, several sound crossings of the 1 m sphere.
TEST(UniformGasAtRest, StaysAtRestEverywhereWithGimpAndAmbientPressureBoundary) {
  SphericalMpm mpm({{air(), 1.0, 1.0, 2.5e5, false}},
                   options(RadialShape::gimp, OuterBoundary::transmitting));
  for (int n = 0; n < 1000; ++n) mpm.advance(mpm.stable_dt());
  const SphericalParticles& p = mpm.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_LT(std::abs(p.velocity[i]), 1e-8) << "particle " << i << " at r = " << p.radius[i];
    ASSERT_NEAR(p.density[i], 1.0, 1e-10) << "particle " << i;
  }
}

// Linear shapes with Gauss-point particles: exact quadrature, so the inside
// stays at rest; the free surface's rarefaction (1 bar into vacuum) has moved
// in by c t = 374 m/s * 0.4 ms = 0.15 m (plus the MUSL spread), so r < 0.6 m is checked.
TEST(UniformGasAtRest, StaysAtRestInsideWithLinearShapes) {
  SphericalOptions o = options(RadialShape::linear, OuterBoundary::free);
  o.margin_cells = 200;  // the surface expands into vacuum at up to 2c/(gamma - 1)
  SphericalMpm mpm({{air(), 1.0, 1.0, 2.5e5, false}}, o);
  while (mpm.time() < 4e-4) mpm.advance(mpm.stable_dt());
  const SphericalParticles& p = mpm.particles();
  for (std::size_t i = 0; i < p.size() && p.radius[i] < 0.6; ++i) {
    ASSERT_LT(std::abs(p.velocity[i]), 1e-8) << "particle " << i << " at r = " << p.radius[i];
    ASSERT_NEAR(p.density[i], 1.0, 1e-10) << "particle " << i;
  }
}

TEST(SphericalSetup, LayerRadiusOffTheGridIsRejected) {
  std::vector<RadialLayer> layers = testing::underwater_layers(1.0);
  layers[0].outer_radius = 0.105;
  EXPECT_THROW(SphericalMpm(layers, options(RadialShape::gimp, OuterBoundary::free)), Error);
}

TEST(SphericalSetup, ExplosiveLayerWithoutDetonationVelocityIsRejected) {
  std::vector<RadialLayer> layers = testing::underwater_layers(1.0);
  layers[0].material.explosive.reset();
  EXPECT_THROW(SphericalMpm(layers, options(RadialShape::gimp, OuterBoundary::free)), Error);
}

TEST(SphericalSetup, LinearTransmittingBoundaryUnderAmbientPressureIsRejected) {
  EXPECT_THROW(SphericalMpm({{air(), 1.0, 1.0, 2.5e5, false}},
                            options(RadialShape::linear, OuterBoundary::transmitting)),
               Error);
}

}  // namespace
}  // namespace mpfd::mpm::spherical
