#pragma once
// The equation of state of a mixed cell during one step. The tracer closure
// (tracer/mixed_cell_closure.hpp, T (3-24)-(3-28)) gives a mixed cell's
// equilibrium pressure only at the end of a step, but a sweep also evaluates
// pressure at the viscous and half-step states of the cell. So at the end of
// each step every mixed cell gets a stiffened gas
//   p = (gamma - 1) rho e - gamma pi,   c^2 = gamma (p + pi) / rho,
// fitted to reproduce the closure's pressure and the mixture's sound speed
// (Wood: 1/(rho c^2) = sum_r theta_r / (rho_r c_r^2)) at the cell state:
//   gamma = 1 + rho c^2 / (rho e + p),   pi = rho c^2 / gamma - p.
// It is exact at the cell state and first-order accurate around it.

#include <cstdint>

#include "common/eos/equation_of_state.hpp"

namespace mpfd::fdm {

/// Material index of a mixed cell in EulerState::material.
inline constexpr std::uint8_t kMixedMaterial = 255;

struct StiffenedGas {
  double gamma;  ///< [-], > 1
  double pinf;   ///< pi [Pa]

  [[nodiscard]] double pressure(double rho, double e) const noexcept {
    return (gamma - 1.0) * rho * e - gamma * pinf;
  }
  [[nodiscard]] double sound_speed(double rho, double e) const noexcept {
    return eos::sound_speed_from_squared(gamma * (pressure(rho, e) + pinf) / rho);
  }
};

/// The stiffened gas through (rho, e, p) with sound speed squared c2. Where
/// rho e + p <= 0 (no such fit), a gas with the cell's pressure and gamma from
/// c2 = gamma p / rho is returned instead.
[[nodiscard]] inline StiffenedGas fit_stiffened_gas(double rho, double e, double p,
                                                    double c2) noexcept {
  const double enthalpy = rho * e + p;
  if (enthalpy > 0.0) {
    const double gamma = 1.0 + rho * c2 / enthalpy;
    return {gamma, rho * c2 / gamma - p};
  }
  const double gamma = p > 0.0 ? rho * c2 / p : 1.4;
  return {gamma, 0.0};
}

}  // namespace mpfd::fdm
