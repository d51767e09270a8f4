// The hoop terms and the StrainStep path of a strength model: a thick elastic
// sphere a = 0.1 m < r < b = 0.2 m (K = 160 GPa, G = 80 GPa, steel-like) holding
// gas at p_i = 10 MPa. A suddenly applied load makes it ring about Lame's static
// solution (Timoshenko & Goodier, thick-walled sphere), with k = b^3/a^3 - 1:
//   sigma_rr = -p_i (b^3/r^3 - 1) / k,  sigma_tt = p_i (b^3/(2 r^3) + 1) / k,
// so the stresses averaged over 1-3 ms (about 30 ringing periods) are compared.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm_solver/spherical/spherical_mpm.hpp"

namespace mpfd::mpm::spherical {
namespace {

TEST(ElasticShell, TimeAveragedStressesMatchLameThickSphere) {
  config::Material gas;
  gas.name = "gas";
  gas.eos = eos::IdealGas{1.4};
  config::Material steel;
  steel.name = "elastic_solid";
  steel.eos = eos::Polynomial{7800.0, 1.6e11, 0.0, 0.0, 0.0, 0.0, 1.6e11, 0.0};
  steel.strength = config::ElasticStrength{8e10};
  const double inner_pressure = 1e7;
  SphericalOptions o;
  o.grid_spacing = 0.002;
  o.outer_boundary = OuterBoundary::free;
  SphericalMpm mpm(
      {{gas, 0.1, 10.0, inner_pressure / (0.4 * 10.0), false}, {steel, 0.2, 7800.0, 0.0, false}},
      o);
  RadialProfile profile;
  std::vector<double> mean_rr;
  std::vector<double> mean_tt;
  int samples = 0;
  while (mpm.time() < 3e-3) {
    mpm.advance(mpm.stable_dt());
    if (mpm.time() < 1e-3) continue;
    mpm.export_profile(profile);
    mean_rr.resize(profile.radius.size(), 0.0);
    mean_tt.resize(profile.radius.size(), 0.0);
    for (std::size_t p = 0; p < profile.radius.size(); ++p) {
      mean_rr[p] += profile.stress_rr[p];
      mean_tt[p] += profile.stress_hoop[p];
    }
    ++samples;
  }
  const double a3 = 1e-3;
  const double b3 = 8e-3;
  const double k = b3 / a3 - 1.0;
  int checked = 0;
  for (std::size_t p = 0; p < profile.radius.size(); ++p) {
    if (profile.layer[p] != 1) continue;
    const double x = b3 / std::pow(profile.radius[p], 3);
    // Measured: within 0.03 p_i (sigma_rr, largest at the bore) and 0.01 p_i (sigma_tt).
    EXPECT_NEAR(mean_rr[p] / samples, -inner_pressure * (x - 1.0) / k, 0.05 * inner_pressure)
        << "r = " << profile.radius[p];
    EXPECT_NEAR(mean_tt[p] / samples, inner_pressure * (0.5 * x + 1.0) / k, 0.05 * inner_pressure)
        << "r = " << profile.radius[p];
    ++checked;
  }
  EXPECT_EQ(checked, 100);
}

}  // namespace
}  // namespace mpfd::mpm::spherical
