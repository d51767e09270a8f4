#include "mpm_solver/material/johnson_cook_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mpm_solver/material/solid_response.hpp"
#include "tests/unit/mpm_solver/material/material_test_support.hpp"
#include "tests/unit/mpm_solver/material/thesis_metals.hpp"

namespace mpfd::mpm {
namespace {

using test_support::PointStorage;
using test_support::ThesisMetal;

// Round-off tolerance of a quantity computed in a few operations from exact inputs.
constexpr double kJcRoundOff = 1e-12;

/// T (2-64) written out independently of johnson_cook_flow_stress.hpp (docs/STYLE: doc and code
/// must not drift).
double documented_flow_stress(const config::JohnsonCook& p, double eps_p, double rate, double t) {
  const double homologous =
      std::clamp((t - p.room_temperature) / (p.melt_temperature - p.room_temperature), 0.0, 1.0);
  return (p.a + p.b * std::pow(eps_p, p.n)) *
         (1.0 + p.c * std::log(std::max(rate / p.reference_strain_rate, 1.0))) *
         (1.0 - std::pow(homologous, p.m));
}

/// A specific heat so large the adiabatic temperature rise is below one ulp of T.
config::JohnsonCook without_heating(config::JohnsonCook p) {
  p.specific_heat = 1e30;
  return p;
}

/// The root of x = f(x) for a decreasing f - x on [0, hi], by bisection to round-off.
template <class F>
double bisect_fixed_point(F f, double hi) {
  double lo = 0.0;
  for (int i = 0; i < 200 && hi - lo > 1e-17; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > mid ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

struct Driver {
  JohnsonCookModel model;
  PointStorage point;
  double rho;

  Driver(const ThesisMetal& metal, const config::JohnsonCook& p) : model(metal.eos, p) {
    rho = metal.eos.rho0;
    auto v = point.view();
    model.initialise(rho, v);
  }
  void step(const StrainStep& s) {
    auto v = point.view();
    model.update(s, v);
    rho = s.density_new;
  }
};

TEST(JohnsonCook, Uniaxial_strain_is_elastic_to_the_HEL_then_follows_A_plus_B_eps_p_to_the_n) {
  for (const double b : {0.0, 275e6}) {  // perfect plasticity, then STEEL-1006 hardening
    const ThesisMetal steel = test_support::steel_1006();
    config::JohnsonCook p = without_heating(steel.strength);
    p.b = b;
    p.c = 0.0;
    const double g = p.shear_modulus;
    Driver d(steel, p);
    double strain = 0.0;
    bool yielded = false;
    for (int i = 0; i < 800; ++i) {
      const double increment = -1e-5;
      d.step(test_support::uniaxial_strain(d.rho, increment));
      strain += increment;
      // sigma_x - sigma_y = s_xx - s_yy; elastic: 2 G eps; yield where it reaches A.
      const double difference = std::abs(d.point.s(0, 0) - d.point.s(1, 1));
      if (2.0 * g * std::abs(strain) < p.a * (1.0 - 1e-12)) {
        EXPECT_EQ(d.point.eps, 0.0) << "strain " << strain;
        EXPECT_NEAR(difference, 2.0 * g * std::abs(strain), kJcRoundOff * difference);
        continue;
      }
      if (!yielded) {
        yielded = true;
        // HEL: sigma_x = -(K + 4G/3) A / (2G) to first order; 1 % covers the
        // Hugoniot's curvature at mu = 2.1e-3 ((2S - 1) mu ~ 0.4 %).
        const double k = steel.eos.rho0 * steel.eos.c0 * steel.eos.c0;
        const double hel = (k + 4.0 * g / 3.0) * p.a / (2.0 * g);
        EXPECT_NEAR(-d.point.stress()(0, 0), hel, 0.01 * hel);
      }
      const double flow = p.a + p.b * std::pow(d.point.eps, p.n);
      EXPECT_NEAR(difference, flow, kJcRoundOff * flow) << "strain " << strain;
      // Prandtl-Reuss on this proportional path: eps_p = 2/3 (|eps| - sigma_y(eps_p) / (2G)).
      const double expected = bisect_fixed_point(
          [&](double x) {
            return 2.0 / 3.0 * (std::abs(strain) - (p.a + p.b * std::pow(x, p.n)) / (2.0 * g));
          },
          std::abs(strain));
      EXPECT_NEAR(d.point.eps, expected, 1e-12) << "strain " << strain;
    }
    EXPECT_TRUE(yielded);
  }
}

TEST(JohnsonCook, Pure_shear_yields_at_tau_equal_sigma_y_over_root_3_and_follows_hardening) {
  for (const double b : {0.0, 426e6}) {  // perfect plasticity, then Al-2024 hardening
    const ThesisMetal al = test_support::al_2024();
    config::JohnsonCook p = without_heating(al.strength);
    p.b = b;
    p.c = 0.0;
    const double g = p.shear_modulus;
    Driver d(al, p);
    double gamma = 0.0;
    for (int i = 0; i < 2000; ++i) {
      d.step(test_support::shear(d.rho, 1e-4));
      gamma += 1e-4;
      const double tau = d.point.s(0, 1);
      EXPECT_EQ(d.point.s(0, 0), 0.0);
      if (std::sqrt(3.0) * g * gamma < p.a * (1.0 - 1e-12)) {
        EXPECT_EQ(d.point.eps, 0.0);
        EXPECT_NEAR(tau, g * gamma, kJcRoundOff * tau);
        continue;
      }
      const double flow = documented_flow_stress(p, d.point.eps, 0.0, d.point.t);
      EXPECT_NEAR(tau, flow / std::sqrt(3.0), kJcRoundOff * tau) << "gamma " << gamma;
      EXPECT_NEAR(von_mises_stress(d.point.s), flow, kJcRoundOff * flow);
      // gamma_p = sqrt(3) eps_p and tau = G (gamma - gamma_p).
      const double expected = bisect_fixed_point(
          [&](double x) {
            return (gamma - (p.a + p.b * std::pow(x, p.n)) / (std::sqrt(3.0) * g)) / std::sqrt(3.0);
          },
          gamma);
      EXPECT_NEAR(d.point.eps, expected, 1e-12) << "gamma " << gamma;
    }
    EXPECT_GT(d.point.eps, 0.1);
  }
}

/// Steady perfectly plastic shear flow at plastic strain rate `rate` [1/s] in
/// steps of dt: the yield stress sqrt(3) tau and the recorded rate.
std::pair<double, double> steady_flow_stress(const config::JohnsonCook& p, double rate,
                                             double dt = 1e-7) {
  const ThesisMetal steel = test_support::steel_1006();
  Driver d(steel, p);
  for (int i = 0; i < 300; ++i) d.step(test_support::shear(d.rho, std::sqrt(3.0) * rate * dt, dt));
  return {std::sqrt(3.0) * d.point.s(0, 1), d.point.history[JohnsonCookModel::kPlasticStrainRate]};
}

TEST(JohnsonCook, Rate_term_scales_the_yield_stress_by_1_plus_C_ln_rate) {
  config::JohnsonCook p = without_heating(test_support::steel_1006().strength);
  p.b = 0.0;
  for (const double rate : {1e3, 1e5}) {
    const auto [flow, recorded] = steady_flow_stress(p, rate);
    // The return map is implicit in the rate; the steady state is reached to round-off.
    EXPECT_NEAR(recorded, rate, 1e-9 * rate);
    EXPECT_NEAR(flow / p.a, 1.0 + p.c * std::log(rate), 1e-9);
  }
  const double ratio = steady_flow_stress(p, 1e5).first / steady_flow_stress(p, 1e3).first;
  EXPECT_NEAR(ratio, (1.0 + p.c * std::log(1e5)) / (1.0 + p.c * std::log(1e3)), 1e-9);
  // Below the reference rate the log is floored: sigma_y = A.
  EXPECT_NEAR(steady_flow_stress(p, 0.1, 1e-2).first, p.a, kJcRoundOff * p.a);
}

TEST(JohnsonCook, Thermal_softening_scales_the_yield_stress_by_1_minus_T_star_to_the_m) {
  const ThesisMetal steel = test_support::steel_1006();
  for (const double m : {1.0, 0.5, 2.0}) {
    config::JohnsonCook p = without_heating(steel.strength);
    p.b = 0.0;
    p.c = 0.0;
    p.m = m;
    const double span = p.melt_temperature - p.room_temperature;
    for (const double t_star : {-0.2, 0.0, 0.3, 0.5, 1.0, 1.5}) {
      Driver d(steel, p);
      d.point.t = p.room_temperature + t_star * span;
      for (int i = 0; i < 100; ++i) d.step(test_support::shear(d.rho, 1e-4));
      const double expected = p.a * (1.0 - std::pow(std::clamp(t_star, 0.0, 1.0), m));
      EXPECT_NEAR(std::sqrt(3.0) * d.point.s(0, 1), expected, kJcRoundOff * p.a)
          << "m " << m << ", T* " << t_star;
    }
  }
}

TEST(JohnsonCook, Plastic_work_is_the_integral_of_sigma_y_over_eps_p_and_heats_by_0_9_of_it) {
  const ThesisMetal al = test_support::al_2024();
  config::JohnsonCook p = without_heating(al.strength);
  p.c = 0.0;
  Driver cold(al, p);
  double sum = 0.0;
  double largest_increment = 0.0;
  for (int i = 0; i < 5000; ++i) {
    const double before = cold.point.eps;
    cold.step(test_support::shear(cold.rho, 1e-4));
    const double increment = cold.point.eps - before;
    largest_increment = std::max(largest_increment, increment);
    sum += von_mises_stress(cold.point.s) * increment;  // the return map's dissipation
  }
  const double eps = cold.point.eps;
  const double work = cold.point.wp * al.eos.rho0;
  EXPECT_NEAR(work, sum, 1e-12 * work);
  // A right Riemann sum of an increasing sigma_y: above the integral by at most
  // max(Delta eps_p) (sigma_y(end) - A). Measured: 5.5e-5 relative.
  const double integral = p.a * eps + p.b * std::pow(eps, p.n + 1.0) / (p.n + 1.0);
  const double bound = largest_increment * p.b * std::pow(eps, p.n);
  EXPECT_GE(work, integral);
  EXPECT_LE(work - integral, bound);
  EXPECT_LT((work - integral) / integral, 1e-4);

  // With Al-2024's c_p = 875 J/(kg K): dT = 0.9 W_p / c_p, and the heat softens the metal.
  config::JohnsonCook heated = al.strength;
  heated.c = 0.0;
  Driver hot(al, heated);
  double t_before = 0.0;
  for (int i = 0; i < 5000; ++i) {
    t_before = hot.point.t;
    hot.step(test_support::shear(hot.rho, 1e-4));
  }
  EXPECT_NEAR(hot.point.t - heated.room_temperature,
              kTaylorQuinney * hot.point.wp / heated.specific_heat, 1e-12 * hot.point.t);
  // gamma = 0.5 of Al-2024: W_p = 4.6e4 J/kg, T rises 47 K (T* = 0.1).
  EXPECT_GT(hot.point.t - heated.room_temperature, 40.0);
  const double softened = documented_flow_stress(heated, hot.point.eps, 0.0, t_before);
  EXPECT_NEAR(von_mises_stress(hot.point.s), softened, kJcRoundOff * softened);
  EXPECT_LT(hot.point.s(0, 1), 0.92 * cold.point.s(0, 1));
}

TEST(JohnsonCook, Failure_strain_zeroes_the_deviator_and_forbids_tension) {
  const ThesisMetal steel = test_support::steel_1006();
  config::JohnsonCook p = steel.strength;
  p.failure_strain = 0.05;
  Driver d(steel, p);
  const double bulk_sound_speed = steel.eos.c0;
  int steps = 0;
  while (d.point.d == 0.0) {
    const double before = d.point.eps;
    d.step(test_support::shear(d.rho, 1e-3));
    ASSERT_LT(++steps, 1000);
    if (d.point.d == 0.0) {
      EXPECT_LT(d.point.eps, 0.05);
      EXPECT_GT(d.point.s(0, 1), 0.0);
    } else {
      EXPECT_LT(before, 0.05);
      EXPECT_GE(d.point.eps, 0.05);
    }
  }
  EXPECT_EQ(d.point.d, 1.0);
  EXPECT_EQ(d.point.s.norm(), 0.0);
  d.step(test_support::shear(d.rho, 1e-3));
  EXPECT_EQ(d.point.s.norm(), 0.0);
  // Pulled apart: no tension, sigma = 0; c is the EOS's alone.
  for (int i = 0; i < 20; ++i) d.step(test_support::uniaxial_strain(d.rho, 1e-3));
  EXPECT_EQ(d.point.p, 0.0);
  EXPECT_EQ(d.point.stress().norm(), 0.0);
  EXPECT_NEAR(d.point.c, bulk_sound_speed, 0.05 * bulk_sound_speed);
  // Pushed back past its reference density: it still carries pressure.
  for (int i = 0; i < 40; ++i) d.step(test_support::uniaxial_strain(d.rho, -1e-3));
  EXPECT_GT(d.point.p, 1e9);
  EXPECT_EQ(d.point.s.norm(), 0.0);
}

TEST(JohnsonCook, Radial_return_lands_on_the_yield_surface_to_1e_12_on_random_paths) {
  // STEEL-1006 with hardening (slope infinite at eps_p = 0), rate term and
  // heating; random symmetric increments up to 3e-2 and steps from 1e-9 to 1e-6 s.
  const ThesisMetal steel = test_support::steel_1006();
  Driver d(steel, steel.strength);
  std::mt19937 random(20261124);
  std::uniform_real_distribution<double> component(-0.03, 0.03);
  std::uniform_real_distribution<double> log_dt(-9.0, -6.0);
  int plastic_steps = 0;
  for (int i = 0; i < 5000; ++i) {
    StrainStep step;
    step.dt = std::pow(10.0, log_dt(random));
    for (int r = 0; r < 3; ++r) {
      for (int c = r; c < 3; ++c)
        step.strain_increment(r, c) = step.strain_increment(c, r) = component(random);
    }
    // Keep the volume near its reference: a slow random walk in tr(Delta eps).
    const double target = d.rho / steel.eos.rho0 - 1.0;
    step.strain_increment.diagonal().array() +=
        target / 3.0 - step.strain_increment.trace() / 3.0 + 0.001 * component(random);
    step.density_old = d.rho;
    step.density_new = d.rho / (1.0 + step.strain_increment.trace());
    const double eps_before = d.point.eps;
    const double t_before = d.point.t;
    d.step(step);
    ASSERT_TRUE(std::isfinite(d.point.s.norm()) && std::isfinite(d.point.p) &&
                std::isfinite(d.point.e) && std::isfinite(d.point.t) && std::isfinite(d.point.c));
    const double rate = d.point.history[JohnsonCookModel::kPlasticStrainRate];
    const double flow = documented_flow_stress(steel.strength, d.point.eps, rate, t_before);
    const double norm = d.point.s.norm();
    if (d.point.eps > eps_before) {
      ++plastic_steps;
      EXPECT_NEAR(rate, (d.point.eps - eps_before) / step.dt, 1e-12 * rate);
      EXPECT_NEAR(norm, std::sqrt(2.0 / 3.0) * flow, 1e-12 * norm) << "step " << i;
    } else {
      EXPECT_LE(norm, std::sqrt(2.0 / 3.0) * flow * (1.0 + 1e-12)) << "step " << i;
    }
  }
  EXPECT_GT(plastic_steps, 2500);
}

}  // namespace
}  // namespace mpfd::mpm
