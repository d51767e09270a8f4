#include "mpm_solver/material/fluid_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/config/scene.hpp"
#include "common/core/error.hpp"
#include "tests/unit/mpm_solver/material/material_test_support.hpp"

namespace mpfd::mpm {
namespace {

using test_support::PointStorage;

StrainStep compression(double rho_old, double ratio) {
  StrainStep step;
  step.dt = 1e-7;
  step.density_old = rho_old;
  step.density_new = rho_old * ratio;
  // (2-20): rho1 = rho0 / (1 + tr), uniaxial along x.
  step.strain_increment(0, 0) = 1.0 / ratio - 1.0;
  return step;
}

TEST(FluidModel, AdiabaticCompressionOfAnIdealGasFollowsTheIsentropeToSecondOrder) {
  const FluidModel air(eos::IdealGas{1.4});
  PointStorage point;
  point.e = 2.0685e5;
  double rho = 1.225;
  auto view = point.view();
  air.initialise(rho, view);
  const double p0 = point.p;
  const int steps = 1000;
  const double ratio = std::pow(2.0, 1.0 / steps);  // to twice the density
  for (int i = 0; i < steps; ++i) {
    auto v = point.view();
    air.update(compression(rho, ratio), v);
    rho *= ratio;
  }
  EXPECT_NEAR(point.p / p0, std::pow(2.0, 1.4), 1e-5 * std::pow(2.0, 1.4));
  EXPECT_NEAR(point.c, std::sqrt(1.4 * point.p / rho), 1e-9 * point.c);
}

TEST(FluidModel, UnburntExplosiveCarriesNoPressureAndBurntCarriesTheEos) {
  const eos::Jwl tnt{1630, 3.712e11, 3.21e9, 4.15, 0.95, 0.3, 6.993e9};
  const FluidModel model(tnt);
  PointStorage point;
  point.e = 6.993e9 / 1630;
  StrainStep still;
  still.dt = 1e-8;
  still.density_old = still.density_new = 1630;
  still.burn_fraction = 0.0;
  auto v = point.view();
  model.update(still, v);
  EXPECT_EQ(point.p, 0.0);
  still.burn_fraction = 1.0;
  model.update(still, v);
  EXPECT_NEAR(point.p, tnt.pressure(1630, 6.993e9 / 1630), 1e-6 * point.p);
  EXPECT_NEAR(point.p, 8.38e9, 0.01e9);  // constant-volume explosion state
}

TEST(MakeConstitutiveModel, GivesAFluidForAMaterialWithoutStrength) {
  config::Material air;
  air.name = "air";
  air.eos = eos::IdealGas{1.4};
  const auto model = make_constitutive_model(air);
  EXPECT_EQ(model->name(), "ideal_gas");
}

}  // namespace
}  // namespace mpfd::mpm
