#pragma once
// Jones-Wilkins-Lee detonation products, T (2-60):
//   p = A (1 - w/(R1 V)) exp(-R1 V) + B (1 - w/(R2 V)) exp(-R2 V) + w E / V
// with V = rho0/rho the relative volume and E = rho0 e the internal energy per
// unit initial volume, so that w E / V = w rho e. Writing p = p_ref(V) + w rho e:
//   dp_ref/dV = A exp(-R1 V) (w/(R1 V^2) + w/V - R1) + (same with B, R2)
//   (dp/drho)_e = -dp_ref/dV V/rho + w e,  (dp/de)_rho = w rho
//   c^2 = (dp/drho)_e + w p / rho
//   e(rho, p) = (p - p_ref(V)) / (w rho)
// Omitted: the unreacted explosive and the burn fraction (program burn scales
// p outside this kernel); the Chapman-Jouguet state is in jwl_cj.hpp.

#include <cmath>
#include <string_view>

#include "common/eos/equation_of_state.hpp"

namespace mpfd::eos {

struct Jwl {
  double rho0 = 0.0;               ///< unreacted explosive density [kg/m^3]
  double a = 0.0;                  ///< A [Pa]
  double b = 0.0;                  ///< B [Pa]
  double r1 = 0.0;                 ///< R1 [-]
  double r2 = 0.0;                 ///< R2 [-]
  double omega = 0.0;              ///< w, Grueneisen coefficient of the products [-]
  double detonation_energy = 0.0;  ///< E0, per unit initial volume [J/m^3]; e0 = E0 / rho0

  [[nodiscard]] static constexpr std::string_view name() noexcept { return "jwl"; }

  /// The e = 0 part of (2-60), p_ref(V) [Pa], and dp_ref/dV [Pa], at relative volume v.
  [[nodiscard]] ValueAndSlope reference_pressure(double v) const noexcept {
    const double term1 = a * std::exp(-r1 * v);
    const double term2 = b * std::exp(-r2 * v);
    return {term1 * (1.0 - omega / (r1 * v)) + term2 * (1.0 - omega / (r2 * v)),  // T (2-60)
            term1 * (omega / (r1 * v * v) + omega / v - r1) +
                term2 * (omega / (r2 * v * v) + omega / v - r2)};
  }

  /// Pressure [Pa] at density rho [kg/m^3] and specific internal energy e [J/kg].
  [[nodiscard]] double pressure(double rho, double e) const noexcept {
    return reference_pressure(rho0 / rho).value + omega * rho * e;  // T (2-60)
  }

  /// Sound speed [m/s] from the analytic c^2 above.
  [[nodiscard]] double sound_speed(double rho, double e) const noexcept {
    const double v = rho0 / rho;
    const ValueAndSlope ref = reference_pressure(v);
    const double p = ref.value + omega * rho * e;
    const double dp_drho = -ref.slope * v / rho + omega * e;
    return sound_speed_from_squared(dp_drho + omega * p / rho);
  }

  /// Specific internal energy [J/kg] giving pressure p [Pa] at density rho.
  [[nodiscard]] double internal_energy(double rho, double p) const noexcept {
    return (p - reference_pressure(rho0 / rho).value) / (omega * rho);  // T (2-60) solved for e
  }
};

/// Throws mpfd::Error unless rho0 > 0, a >= 0, b >= 0, r1 > r2 > 0,
/// 0 < omega < 1 and detonation_energy > 0.
void validate(const Jwl& eos);

}  // namespace mpfd::eos
