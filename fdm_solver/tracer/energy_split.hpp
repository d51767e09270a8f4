#pragma once
// Specific internal energies of the two materials of a mixed cell, T §3.3.
// T's assumption (2): the cell's increment is shared by volume fraction,
//   e_r^n = e_r^{n-1} + theta_r delta_e_c                    T §3.3 (2)
// What T leaves open: this split does not keep the materials' energy equal to
// the cell's, theta_1 rho_1 e_1 + theta_2 rho_2 e_2 = rho_c e_c; with mass
// fractions y_r = theta_r rho_r / rho_c it adds (y_1 theta_1 + y_2 theta_2)
// delta_e_c, not delta_e_c (half of it when a light material fills half the
// cell), and the gap accumulates. The solver's conserved cell energy is what
// counts; the e_r only set the equilibrium pressure. So the closure keeps the
// ratio e_1 : e_2 of the split and scales both by the common factor s with
//   y_1 s e_1 + y_2 s e_2 = e_c,
// the y_r being those of the equilibrium it solves (s is part of its residual,
// mixed_cell_closure.hpp). A common factor, not a common increment, keeps both
// energies positive when e_c > 0. A split energy <= 0 (an undershoot) has no
// meaningful ratio: both are then reset to e_c.

namespace mpfd::fdm {

/// e_r^n [J/kg] from e_r^{n-1}, theta_r and the cell's increment delta_e_c.
[[nodiscard]] inline double split_energy_increment(double e_previous, double theta,
                                                   double cell_increment) noexcept {
  return e_previous + theta * cell_increment;  // T §3.3 assumption (2)
}

struct EnergyPair {
  double first;
  double second;
};

/// The split energies to rescale: as given if both are > 0, else both e_c.
[[nodiscard]] inline EnergyPair energies_to_rescale(EnergyPair split, double cell_energy) noexcept {
  return split.first > 0.0 && split.second > 0.0 ? split : EnergyPair{cell_energy, cell_energy};
}

/// Common factor s with y_1 s e_1 + y_2 s e_2 = e_c (1 if the sum is 0).
[[nodiscard]] inline double energy_scale(double y1, double y2, EnergyPair e,
                                         double cell_energy) noexcept {
  const double sum = y1 * e.first + y2 * e.second;
  return sum != 0.0 ? cell_energy / sum : 1.0;
}

}  // namespace mpfd::fdm
