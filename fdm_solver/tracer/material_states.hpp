#pragma once
// Per-cell, per-material state the FDM cell does not hold: the specific
// internal energy e_r and density rho_r of each material present, and the
// cell pressure from them. Single-material cells: p = f_m(rho_c, e_c), and
// e_m = e_c, rho_m = rho_c. Mixed cells: the increment of e_c since the last
// update is split by volume fraction (T §3.3 (2), energy_split.hpp), then the
// closure (3-24)-(3-28) with the cell energy conserved gives rho_r, e_r, p_e.
// A material new to a mixed cell starts from the mean e_r of the face
// neighbours that held it at the last update (e_c of the cell if none) --
// T does not say where its e_r^{n-1} comes from.

#include <cstddef>
#include <span>
#include <vector>

#include "common/eos/any_eos.hpp"
#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/material_map.hpp"
#include "fdm_solver/tracer/mixed_cell_closure.hpp"

namespace mpfd::fdm {

struct MaterialStates {
  std::size_t cell_count = 0;
  std::vector<double> energy;         ///< e_r [J/kg] at [r * cells + cell]; valid where theta_r > 0
  std::vector<double> density;        ///< rho_r [kg/m^3], same layout and validity
  std::vector<double> cell_energy;    ///< e_c [J/kg] at the last update, for delta_e_c
  std::vector<ClosureStatus> status;  ///< per cell, from the last update

  MaterialStates() = default;
  /// e_r = e_c and rho_r = rho_c for every material present in `map`.
  MaterialStates(const MaterialMap& map, std::span<const double> rho, std::span<const double> e);

  [[nodiscard]] std::size_t at(int r, std::size_t cell) const {
    return static_cast<std::size_t>(r) * cell_count + cell;
  }
};

struct ClosureReport {
  std::size_t mixed_cells = 0;
  std::size_t iteration_limits = 0;  ///< closures stopped by the iteration limit
  std::size_t fallbacks = 0;         ///< closures without a root (ClosureStatus::fallback)
};

/// The counts of the last update, from the closure status of every cell.
[[nodiscard]] ClosureReport closure_report(const MaterialStates& states);

/// Cell pressure [Pa] for every cell from rho_c, e_c (grid order) and the
/// classification `current`; `previous` is the classification at the last
/// call (it tells which materials are new to a cell). `eos[r]` is the EOS of
/// material r. Throws mpfd::Error on a size mismatch.
ClosureReport update_cell_pressure(const grid::UniformGrid& grid, std::span<const eos::AnyEos> eos,
                                   const MaterialMap& previous, const MaterialMap& current,
                                   std::span<const double> rho, std::span<const double> e,
                                   MaterialStates& states, std::span<double> pressure);

}  // namespace mpfd::fdm
