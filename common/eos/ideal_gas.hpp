#pragma once
// Ideal gas, T (2-59): p = (gamma - 1) rho e.
//   (dp/drho)_e = (gamma - 1) e,  (dp/de)_rho = (gamma - 1) rho
//   c^2 = (gamma - 1) e + p/rho^2 (gamma - 1) rho = gamma (gamma - 1) e
//   e(rho, p) = p / ((gamma - 1) rho)
// Omitted: the kinetic-energy split of (2-59) (callers pass e, not total E);
// no vacuum or e < 0 treatment beyond the c^2 floor.

#include <string_view>

#include "common/eos/equation_of_state.hpp"

namespace mpfd::eos {

struct IdealGas {
  double gamma = 1.4;  ///< ratio of specific heats [-], > 1

  [[nodiscard]] static constexpr std::string_view name() noexcept { return "ideal_gas"; }

  /// Pressure [Pa] at density rho [kg/m^3] and specific internal energy e [J/kg].
  [[nodiscard]] double pressure(double rho, double e) const noexcept {
    return (gamma - 1.0) * rho * e;  // T (2-59)
  }

  /// Sound speed [m/s], c^2 = gamma (gamma - 1) e (independent of rho).
  [[nodiscard]] double sound_speed(double /*rho*/, double e) const noexcept {
    return sound_speed_from_squared(gamma * (gamma - 1.0) * e);
  }

  /// Specific internal energy [J/kg] giving pressure p [Pa] at density rho.
  [[nodiscard]] double internal_energy(double rho, double p) const noexcept {
    return p / ((gamma - 1.0) * rho);  // T (2-59) solved for e
  }
};

/// Throws mpfd::Error unless gamma > 1.
void validate(const IdealGas& eos);

}  // namespace mpfd::eos
