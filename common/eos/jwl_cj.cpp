#include "common/eos/jwl_cj.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::eos {
namespace {

/// (1 - V)^2 d/dV [pH/(1 - V)]: negative left of a minimum of the Rayleigh
/// slope, positive right of it, zero at the tangent point.
double tangency_residual(const Jwl& eos, double v) {
  const ValueAndSlope hugoniot = products_hugoniot(eos, v);
  return hugoniot.slope * (1.0 - v) + hugoniot.value;
}

double rayleigh_slope(const Jwl& eos, double v) {
  return products_hugoniot(eos, v).value / (1.0 - v);
}

/// Scan resolution: brackets every minimum of the Rayleigh slope wider than
/// 1/512 of (omega/(2+omega), 1); TNT's is a single smooth minimum.
constexpr int kScanIntervals = 512;

}  // namespace

ValueAndSlope products_hugoniot(const Jwl& eos, double v) noexcept {
  const ValueAndSlope ref = eos.reference_pressure(v);
  const double w = eos.omega;
  const double numerator = ref.value + w * eos.detonation_energy / v;
  const double numerator_slope = ref.slope - w * eos.detonation_energy / (v * v);
  const double denominator = 1.0 - w * (1.0 - v) / (2.0 * v);
  const double denominator_slope = w / (2.0 * v * v);
  return {numerator / denominator, (numerator_slope * denominator - numerator * denominator_slope) /
                                       (denominator * denominator)};
}

ChapmanJouguetState chapman_jouguet_state(const Jwl& eos) {
  validate(eos);
  // Bracket each minimum of the Rayleigh slope (residual - to +) and keep the
  // least one: the CJ detonation is the slowest self-sustained one.
  const double v_pole = eos.omega / (2.0 + eos.omega);
  const double step = (1.0 - v_pole) / kScanIntervals;
  double lo = 0.0;
  double hi = 0.0;
  double least_slope = std::numeric_limits<double>::infinity();
  double v_prev = v_pole + step;
  double residual_prev = tangency_residual(eos, v_prev);
  for (int i = 2; i < kScanIntervals; ++i) {
    const double v = v_pole + i * step;
    const double residual = tangency_residual(eos, v);
    if (residual_prev < 0.0 && residual >= 0.0) {
      const double slope = std::fmin(rayleigh_slope(eos, v_prev), rayleigh_slope(eos, v));
      if (slope < least_slope) {
        least_slope = slope;
        lo = v_prev;
        hi = v;
      }
    }
    v_prev = v;
    residual_prev = residual;
  }
  if (!(least_slope < std::numeric_limits<double>::infinity())) {
    throw Error("jwl: the products' Hugoniot has no Chapman-Jouguet point for V in (" +
                shortest_text(v_pole) + ", 1): check a, b, r1, r2, omega and detonation_energy");
  }
  // Bisection on the sign of the residual, down to adjacent doubles.
  for (double mid = 0.5 * (lo + hi); mid > lo && mid < hi; mid = 0.5 * (lo + hi)) {
    if (tangency_residual(eos, mid) < 0.0) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  const double v = 0.5 * (lo + hi);
  const double p = products_hugoniot(eos, v).value;
  const double d = std::sqrt(p / (eos.rho0 * (1.0 - v)));  // Rayleigh line
  return {.pressure = p,
          .detonation_velocity = d,
          .density = eos.rho0 / v,
          .particle_velocity = d * (1.0 - v)};
}

}  // namespace mpfd::eos
