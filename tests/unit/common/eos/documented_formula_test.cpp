// Doc and code must not drift (docs/STYLE.md): each formula in the model
// headers' comments is written out again here, from the comment, and compared
// with the kernel. A kernel change that the comment does not follow (or the
// reverse) fails here.

#include <gtest/gtest.h>

#include <cmath>

#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::eos {
namespace {

using test_materials::kAir;
using test_materials::kSteel;
using test_materials::kTnt;
using test_materials::kWater;

// Same formula, other operation order: agreement to round-off. The states
// below avoid cancellation between terms, so 1e-12 relative is ample.
constexpr double kTolerance = 1e-12;

void expect_same(double documented, double kernel) {
  EXPECT_NEAR(kernel, documented, kTolerance * std::abs(documented));
}

// e = (p - p_ref)/(dp/de) may cancel (e = 0 states): the error scales with the
// largest term, e + |p|/(dp/de), not with e.
void expect_same_energy(double documented, double kernel, double scale) {
  EXPECT_NEAR(kernel, documented, kTolerance * scale);
}

TEST(DocumentedFormula, IdealGas_pressure_sound_speed_and_energy_match_header) {
  const double g = kAir.gamma;
  for (const double rho : {0.05, 1.225, 6.0}) {
    for (const double e : {5.0e4, 2.0685e5, 1.0e6}) {
      const double p = (g - 1.0) * rho * e;  // p = (gamma - 1) rho e
      expect_same(p, kAir.pressure(rho, e));
      expect_same(std::sqrt(g * (g - 1.0) * e), kAir.sound_speed(rho, e));  // c^2 = g (g-1) e
      expect_same(std::sqrt(g * p / rho), kAir.sound_speed(rho, e));        // = gamma p / rho
      expect_same_energy(e, kAir.internal_energy(rho, p), e);
    }
  }
}

TEST(DocumentedFormula, Jwl_pressure_sound_speed_and_energy_match_header) {
  const double a = kTnt.a;
  const double b = kTnt.b;
  const double r1 = kTnt.r1;
  const double r2 = kTnt.r2;
  const double w = kTnt.omega;
  for (const double v : {0.6, 1.0, 2.0, 7.0}) {
    for (const double e : {1.0e6, 4.29e6}) {
      const double rho = kTnt.rho0 / v;
      const double big_e = kTnt.rho0 * e;  // E = rho0 e, per unit initial volume
      const double p_ref = a * (1.0 - w / (r1 * v)) * std::exp(-r1 * v) +
                           b * (1.0 - w / (r2 * v)) * std::exp(-r2 * v);
      const double p = p_ref + w * big_e / v;
      const double dp_ref_dv = a * std::exp(-r1 * v) * (w / (r1 * v * v) + w / v - r1) +
                               b * std::exp(-r2 * v) * (w / (r2 * v * v) + w / v - r2);
      const double dp_drho = -dp_ref_dv * v / rho + w * e;
      const double c2 = dp_drho + w * p / rho;
      expect_same(p, kTnt.pressure(rho, e));
      expect_same(w * big_e / v, w * rho * e);  // the header's w E / V = w rho e
      expect_same(std::sqrt(c2), kTnt.sound_speed(rho, e));
      expect_same_energy((p - p_ref) / (w * rho), kTnt.internal_energy(rho, p),
                         e + std::abs(p_ref) / (w * rho));
    }
  }
}

TEST(DocumentedFormula, MieGruneisen_pressure_sound_speed_and_energy_match_header) {
  const double rho0 = kSteel.rho0;
  const double c0 = kSteel.c0;
  const double s = kSteel.s;
  const double g = kSteel.gamma0;
  for (const double mu : {-0.1, -0.03, 0.04, 0.3}) {
    for (const double e : {0.0, 2.0e5}) {
      const double rho = rho0 * (1.0 + mu);
      const double ph =
          mu > 0.0
              ? rho0 * c0 * c0 *
                    (mu + (2.0 * s - 1.0) * mu * mu + (s - 1.0) * (3.0 * s - 1.0) * mu * mu * mu)
              : rho0 * c0 * c0 * mu;
      const double ph_slope =
          mu > 0.0
              ? rho0 * c0 * c0 *
                    (1.0 + 2.0 * (2.0 * s - 1.0) * mu + 3.0 * (s - 1.0) * (3.0 * s - 1.0) * mu * mu)
              : rho0 * c0 * c0;
      const double p = ph * (1.0 - g * mu / 2.0) + g * rho * e;
      const double dp_drho = (ph_slope * (1.0 - g * mu / 2.0) - g * ph / 2.0) / rho0 + g * e;
      const double c2 = dp_drho + g * p / rho;
      expect_same(p, kSteel.pressure(rho, e));
      expect_same(std::sqrt(c2), kSteel.sound_speed(rho, e));
      expect_same_energy((p - ph * (1.0 - g * mu / 2.0)) / (g * rho),
                         kSteel.internal_energy(rho, p), e + std::abs(p) / (g * rho));
    }
  }
}

TEST(DocumentedFormula, Polynomial_pressure_sound_speed_and_energy_match_header) {
  const Polynomial& w = kWater;
  for (const double mu : {-0.1, -0.02, 0.05, 0.4}) {
    for (const double e : {0.0, 1.0e6}) {
      const double rho = w.rho0 * (1.0 + mu);
      const bool compressed = mu > 0.0;
      const double p_ref = compressed ? w.a1 * mu + w.a2 * mu * mu + w.a3 * mu * mu * mu
                                      : w.t1 * mu + w.t2 * mu * mu;
      const double b = compressed ? w.b0 + w.b1 * mu : w.b0;
      const double p = p_ref + b * w.rho0 * e;
      const double dp_ref_dmu =
          compressed ? w.a1 + 2.0 * w.a2 * mu + 3.0 * w.a3 * mu * mu : w.t1 + 2.0 * w.t2 * mu;
      const double dp_drho = dp_ref_dmu / w.rho0 + (compressed ? w.b1 * e : 0.0);
      const double c2 = dp_drho + p / (rho * rho) * b * w.rho0;
      expect_same(p, w.pressure(rho, e));
      expect_same(std::sqrt(c2), w.sound_speed(rho, e));
      expect_same_energy((p - p_ref) / (b * w.rho0), w.internal_energy(rho, p),
                         e + std::abs(p) / (b * w.rho0));
    }
  }
}

}  // namespace
}  // namespace mpfd::eos
