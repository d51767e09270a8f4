#pragma once
// Artificial bulk viscosity, linear plus quadratic (S, the "人工黏性"
// paragraph; the von Neumann-Richtmyer/Landshoff form used by LS-DYNA and
// MPM3D): in compression (volumetric strain rate d < 0)
//   q = rho l (c0 l d^2 - c1 c d),
// otherwise q = 0; l is the smallest background cell size (S: "in MPM, the
// smallest grid size"), rho the current density and c the sound speed. It
// smears a shock over a few cells instead of letting it ring.

namespace mpfd::mpm {

struct BulkViscosity {
  double quadratic = 1.5;  ///< c0 [-]
  double linear = 0.06;    ///< c1 [-]
  double length = 0.0;     ///< l [m]

  /// q [Pa] for volumetric strain rate `rate` [1/s], density rho, sound speed c.
  [[nodiscard]] double operator()(double rate, double rho, double c) const noexcept {
    if (rate >= 0.0) return 0.0;
    return rho * length * (quadratic * length * rate * rate - linear * c * rate);
  }
};

}  // namespace mpfd::mpm
