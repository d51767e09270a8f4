#pragma once
// The tracker state of an FDM zone whose cells and tracers arrive from
// outside (an AFDMP handoff, T §3.2.1 -> §3.2.2: the MPM particles of the
// fluid zone become massless tracers, T (3-3)-(3-8)). Only positions and
// materials arrive, so the state is built as a fresh start would build it:
// bin, classify by tracer counts (T (3-23) with equal carried volumes), give
// tracer-free cells the nearest material (empty_cell_fill.hpp), assign the
// carried volumes (T (3-21), (3-22)), and start every material of a cell from
// the cell's own state, e_r = e_c and rho_r = rho_c (T is silent on the first
// closure after a handoff; the closure then splits rho_c among the materials).
// With a MaterialStartView (each material's own state, which the coupler
// takes from the MPM particles, coupler/handoff/material_start.hpp) a mixed
// cell whose start holds exactly its two materials, each with theta_r > 0 and
// finite rho_r > 0, e_r > 0, takes theta_r (normalised over the pair; the
// tracers' carried volumes follow, T (3-22)), rho_r and e_r from it; any other
// mixed cell, and every single-material cell, starts from the cell's state.

#include <functional>
#include <span>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/multi_material_tracker.hpp"

namespace mpfd::fdm {

/// Each material's own start in the cells, laid out [r * cells + cell] as
/// MaterialStates (grid order). All empty: none.
struct MaterialStartView {
  std::span<const double> volume_fraction;  ///< theta_r [-]
  std::span<const double> density;          ///< rho_r [kg/m^3]
  std::span<const double> energy;           ///< e_r [J/kg]

  [[nodiscard]] bool empty() const { return volume_fraction.empty(); }
};

/// The tracker state of `points` (positions and materials; their volumes are
/// ignored) on `grid` with `material_count` materials, cell density `density`
/// [kg/m^3] and specific internal energy `energy` [J/kg] (grid order).
/// `fallback_material` (one per cell) classifies the cells only when no tracer
/// at all lies in the grid. `start`, if not empty, is each material's own
/// state (see above). Throws mpfd::Error naming the first tracer outside
/// the grid or with a material outside [0, material_count), a fallback
/// material outside that range, a cell holding three materials, or a size
/// mismatch; all of these before `accepted` is
/// called, once, after which nothing throws but for memory (a solver
/// releases the tracker this one replaces there: one tracker at a time).
[[nodiscard]] TrackerState tracker_from_points(const grid::UniformGrid& grid, int material_count,
                                               TracerSet points,
                                               std::span<const int> fallback_material,
                                               std::span<const double> density,
                                               std::span<const double> energy,
                                               const MaterialStartView& start = {},
                                               const std::function<void()>& accepted = {});

}  // namespace mpfd::fdm
