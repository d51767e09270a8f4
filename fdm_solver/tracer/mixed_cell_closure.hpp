#pragma once
// Mixed-cell closure, T §3.3 (3-24)-(3-28): two materials share a cell of
// density rho_c with volume fractions theta_1 (from the tracers, T (3-23))
// and theta_2 = 1 - theta_1 (3-27), at specific internal energies e_1, e_2
// (after the split, energy_split.hpp; (3-25), (3-26)). Find rho_1, rho_2 with
//   p_e = f_1(rho_1, e_1) = f_2(rho_2, e_2)                        T (3-24)
//   theta_1 rho_1 + theta_2 rho_2 = rho_c                          T (3-28)
// One unknown, rho_1 in [0, rho_c/theta_1]. It is solved as the mass fraction
// w in [0, 1/2] of the material holding less of the cell's mass (rho = w rho_c
// / theta), the other density being (1 - w) rho_c / theta from (3-28): so both
// keep full relative precision when one material has 1e-9 of the mass.
// f_1 - f_2 is sampled at y_1 = theta_1 rho_1 / rho_c = 0, 1/2, 1 and, if
// those do not bracket a root, at y_1 and 1 - y_1 = 2^-k / 2 (k = 0..40): the
// first sign change from y_1 = 0 is taken (JWL's p(rho) turns down at extreme
// compression, so a sliver of products in a dense cell has two roots; the
// first is on the physical branch). The root is found by bracketed Newton
// (bracketed_newton.hpp) to |f_1 - f_2| <= 1e-12 max(|f_1|, |f_2|), or after
// 60 iterations (status iteration_limit).
// Fallback, with no sign change (or theta_1 outside (0, 1), rho_c <= 0 or a
// non-finite input):
// rho_1 = rho_2 = rho_c, p_e = theta_1 f_1(rho_c, e_1) + theta_2 f_2(rho_c,
// e_2), status fallback; finite for finite inputs, never a silent NaN.
// With cell_energy set, e_1 and e_2 are scaled by the common factor that makes
// y_1 e_1 + y_2 e_2 = e_c at the solution (energy_split.hpp).

#include <cstdint>
#include <optional>

#include "common/eos/any_eos.hpp"

namespace mpfd::fdm {

enum class ClosureStatus : std::uint8_t { single_material, converged, iteration_limit, fallback };

struct MixedCellInput {
  double rho_c = 0.0;                 ///< cell density [kg/m^3]
  double theta1 = 0.0;                ///< volume fraction of material 1 [-], in (0, 1)
  double e1 = 0.0;                    ///< specific internal energy of material 1 [J/kg]
  double e2 = 0.0;                    ///< specific internal energy of material 2 [J/kg]
  std::optional<double> cell_energy;  ///< e_c [J/kg]: rescale e1, e2 to conserve it
};

struct MixedCellState {
  double rho1 = 0.0;      ///< [kg/m^3]
  double rho2 = 0.0;      ///< [kg/m^3]
  double e1 = 0.0;        ///< [J/kg], rescaled if cell_energy was set
  double e2 = 0.0;        ///< [J/kg]
  double pressure = 0.0;  ///< p_e = theta_1 f_1 + theta_2 f_2 [Pa]
  int iterations = 0;
  ClosureStatus status = ClosureStatus::fallback;
};

/// Pressure equilibrium of a mixed cell, T (3-24), (3-28). A point kernel:
/// no allocation, no throw.
[[nodiscard]] MixedCellState close_mixed_cell(const eos::AnyEos& eos1, const eos::AnyEos& eos2,
                                              const MixedCellInput& in) noexcept;

}  // namespace mpfd::fdm
