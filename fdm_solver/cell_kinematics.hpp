#pragma once
// Per-cell quantities shared by the sweep kernel and the stable-dt scan, so
// that both give the same bits for the same cell (the step size computed in
// the last sweep of a step must equal a separate scan of the grid). Each takes
// 1/rho, computed once per cell: one division instead of one per use.

#include <cmath>

namespace mpfd::fdm {

/// Specific internal energy e = (E - |m|^2 / (2 rho)) / rho [J/kg] from the
/// conserved state; m1, m2, m3 in a fixed order (x, y, z for the stable dt).
[[nodiscard]] inline double internal_energy_per_mass(double inv_rho, double m1, double m2,
                                                     double m3, double e_total) noexcept {
  return (e_total - 0.5 * (m1 * m1 + m2 * m2 + m3 * m3) * inv_rho) * inv_rho;
}

/// How many cells per second a signal crosses along an axis, (|u| + c) / dx
/// [1/s]; the stable step is set by the largest (its inverse: a crossing time).
[[nodiscard]] inline double crossing_rate(double inv_dx, double momentum, double inv_rho,
                                          double sound_speed) noexcept {
  return (std::abs(momentum * inv_rho) + sound_speed) * inv_dx;
}

}  // namespace mpfd::fdm
