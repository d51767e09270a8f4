#include "mpm_solver/material/elastic_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "mpm_solver/material/johnson_cook_model.hpp"
#include "tests/unit/mpm_solver/material/material_test_support.hpp"
#include "tests/unit/mpm_solver/material/thesis_metals.hpp"

namespace mpfd::mpm {
namespace {

using test_support::PointStorage;

TEST(ElasticModel, Uniaxial_strain_gives_sigma_x_equal_K_plus_4G_over_3_times_eps) {
  const test_support::ThesisMetal steel = test_support::steel_1006();
  const double rho0 = steel.eos.rho0;
  const double k = rho0 * steel.eos.c0 * steel.eos.c0;
  const double g = steel.strength.shear_modulus;
  // A polynomial EOS linear in mu isolates the elastic law from the Hugoniot's curvature.
  const eos::Polynomial linear{rho0, k, 0.0, 0.0, 0.0, 0.0, k, 0.0};
  const ElasticModel model(linear, g);
  for (const double eps : {-1e-6, 1e-6}) {
    PointStorage point;
    auto v = point.view();
    model.initialise(rho0, v);
    EXPECT_NEAR(point.c * point.c, (k + 4.0 * g / 3.0) / rho0, 1e-12 * point.c * point.c);
    model.update(test_support::uniaxial_strain(rho0, eps), v);
    EXPECT_NEAR(point.s(0, 0), 4.0 * g / 3.0 * eps, 1e-12 * std::abs(point.s(0, 0)));
    EXPECT_NEAR(point.s(1, 1), -2.0 * g / 3.0 * eps, 1e-12 * std::abs(point.s(1, 1)));
    // The EOS sees mu = rho/rho0 - 1 = -eps / (1 + eps) (2-20); 1e-9 is the
    // round-off of mu = 1e-6 formed from densities near 7890.
    EXPECT_NEAR(point.p, k * (1.0 / (1.0 + eps) - 1.0), 1e-9 * std::abs(point.p));
    const double sigma_x = point.stress()(0, 0);
    const double linearised = (k + 4.0 * g / 3.0) * eps;
    // mu = -eps + eps^2 - ...: the small-strain law holds to O(eps) relative.
    EXPECT_NEAR(sigma_x, linearised, std::abs(eps) * std::abs(linearised));
    // With the thesis's Mie-Grueneisen steel: (2S - 1 + gamma/2 + 1) |eps| ~ 4 |eps|.
    const ElasticModel mg(steel.eos, g);
    PointStorage other;
    auto w = other.view();
    mg.initialise(rho0, w);
    mg.update(test_support::uniaxial_strain(rho0, eps), w);
    EXPECT_NEAR(other.stress()(0, 0), linearised, 5.0 * std::abs(eps) * std::abs(linearised));
  }
}

/// Loads a point along rho -> rho (1 + 1e-4)^100 with 1e-4 shear per step,
/// then unloads along the same densities and shears: e, p and s must return.
template <class Model>
void expect_closed_cycle_returns_the_energy(const Model& model, double rho0) {
  PointStorage point;
  point.e = 1e4;
  auto v = point.view();
  model.initialise(rho0, v);
  const double e0 = point.e;
  const double p0 = point.p;
  std::vector<double> rho{rho0};
  double peak_e = 0.0;
  for (int i = 0; i < 100; ++i) {
    rho.push_back(rho.back() * (1.0 + 1e-4));
    model.update(test_support::volume_and_shear(rho[i], rho[i + 1], 1e-4), v);
    peak_e = std::max(peak_e, std::abs(point.e - e0));
  }
  const double peak_s = point.s.norm();
  const double peak_p = std::abs(point.p - p0);
  for (int i = 100; i > 0; --i)
    model.update(test_support::volume_and_shear(rho[i], rho[i - 1], -1e-4), v);
  // 200 steps of round-off in e, p and s.
  EXPECT_NEAR(point.e, e0, 1e-12 * peak_e) << model.name();
  EXPECT_NEAR(point.p, p0, 1e-12 * peak_p) << model.name();
  EXPECT_NEAR(point.s.norm(), 0.0, 1e-12 * peak_s) << model.name();
  EXPECT_GT(peak_e, 100.0);  // the cycle did work: ~1.1e3 J/kg at the peak
}

TEST(ElasticModel, Closed_elastic_cycle_returns_the_internal_energy_to_round_off) {
  const test_support::ThesisMetal steel = test_support::steel_1006();
  expect_closed_cycle_returns_the_energy(ElasticModel(steel.eos, steel.strength.shear_modulus),
                                         steel.eos.rho0);
  // Johnson-Cook below yield is the same elastic law.
  config::JohnsonCook strong = steel.strength;
  strong.a = 1e11;
  expect_closed_cycle_returns_the_energy(JohnsonCookModel(steel.eos, strong), steel.eos.rho0);
}

TEST(ElasticModel, Deviatoric_work_is_stored_as_internal_energy) {
  // Pure shear at constant volume: e rises by tau^2 / (2 G rho), the strain energy.
  const test_support::ThesisMetal steel = test_support::steel_1006();
  const double g = steel.strength.shear_modulus;
  const double rho = steel.eos.rho0;
  const ElasticModel model(steel.eos, g);
  PointStorage point;
  auto v = point.view();
  model.initialise(rho, v);
  for (int i = 0; i < 50; ++i) model.update(test_support::shear(rho, 2e-5), v);
  const double tau = point.s(0, 1);
  EXPECT_NEAR(tau, g * 1e-3, 1e-12 * tau);
  EXPECT_NEAR(point.e, tau * tau / (2.0 * g * rho), 1e-12 * point.e);
}

}  // namespace
}  // namespace mpfd::mpm
