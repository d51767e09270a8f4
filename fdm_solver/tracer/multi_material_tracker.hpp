#pragma once
// The FDM solver's multi-material step (T §3.2.2, §3.3) in two calls:
//   1. advect(v^n, dt, faces), before or after the sweeps but with the
//      velocities of time level n: tracers move (3-9)-(3-13), are binned,
//      cells are classified with theta_r (3-23), and each tracer gets the
//      volume it carries into the next step (3-21), (3-22);
//   2. update_pressure(rho, e, p) with the cell density and specific internal
//      energy after the sweeps: the cell pressure, single-material cells from
//      their EOS, mixed cells from the closure (3-24)-(3-28).
// Call each exactly once per step, in this order; update_pressure right after
// construction gives the initial pressure. Fields are plain arrays in the
// grid's cell order (x fastest, no ghost cells). Between steps the whole state
// the next step reads is TrackerState (a checkpoint saves and restores it).
// The constructor's tracers are seeded at their first use (advect(), tracers(),
// bins()), from the cell materials it was given: an AFDMP FDM whose cells and
// tracers arrive by import before its first step never seeds the whole grid
// (8 tracers per cell: 0.94 GB with their bins on V4's 125^3 far octant).

#include <span>
#include <vector>

#include "common/eos/any_eos.hpp"
#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/empty_cell_fill.hpp"
#include "fdm_solver/tracer/material_map.hpp"
#include "fdm_solver/tracer/material_states.hpp"
#include "fdm_solver/tracer/tracer_advection.hpp"
#include "fdm_solver/tracer/tracer_bins.hpp"
#include "fdm_solver/tracer/tracer_set.hpp"

namespace mpfd::fdm {

/// What the next step reads of a tracker between steps (besides the cell
/// fields): the tracers with their carried volumes; the classification with
/// theta_r (after update_pressure() the previous one is the current one); and
/// e_r, rho_r, e_c with the closure status (material_states.hpp). The bins and
/// scratch are rebuilt from these.
struct TrackerState {
  TracerSet tracers;
  MaterialMap materials;
  MaterialStates states;
};

class MultiMaterialTracker {
 public:
  /// `materials[r]` is the EOS of material index r (the scene's material
  /// order); `cell_material`, `density` [kg/m^3] and `energy` [J/kg] are the
  /// initial cell fields. Seeds tracers_per_axis^d tracers per cell at their
  /// first use (see the file comment). Throws mpfd::Error on a size mismatch,
  /// an invalid EOS, a material index without an EOS or tracers_per_axis < 1.
  MultiMaterialTracker(const grid::UniformGrid& grid, std::vector<eos::AnyEos> materials,
                       std::span<const double> cell_material, std::span<const double> density,
                       std::span<const double> energy, int tracers_per_axis);
  /// A tracker that continues from `state` (as restore(); e.g. built by
  /// tracker_from_points). Throws mpfd::Error as restore() and the constructor above.
  MultiMaterialTracker(const grid::UniformGrid& grid, std::vector<eos::AnyEos> materials,
                       TrackerState state);

  /// Step part 1; see the file comment.
  AdvectionReport advect(const VelocityView& velocity, double dt, const TracerBoundaries& faces);
  /// Step part 2: writes the cell pressure [Pa]; see the file comment.
  ClosureReport update_pressure(std::span<const double> density, std::span<const double> energy,
                                std::span<double> pressure);

  /// Seeds the constructor's tracers if they are still pending (not thread-safe:
  /// the thread that steps the tracker reads it).
  [[nodiscard]] const TracerSet& tracers() const;
  [[nodiscard]] const TracerBins& bins() const;
  /// The constructor's tracers are not seeded yet (no advect(), tracers(),
  /// bins() or restore() since).
  [[nodiscard]] bool tracers_pending() const { return pending_tracers_per_axis_ > 0; }
  /// Classification and theta_r after the last advect().
  [[nodiscard]] const MaterialMap& materials() const { return current_; }
  /// e_r, rho_r and closure status after the last update_pressure().
  [[nodiscard]] const MaterialStates& states() const { return states_; }

  /// Continues from a saved state (tracers(), materials(), states() taken
  /// between steps): the next steps are bit for bit those of the tracker that
  /// had it. Throws mpfd::Error naming the first array whose size or values do
  /// not fit this grid and material count (a tracer outside the grid, a
  /// material index out of range); the tracker is then unchanged.
  void restore(TrackerState state);

 private:
  /// Seeds tracers_ and bins_ from current_ if the constructor left them pending.
  void seed_if_pending() const;

  grid::UniformGrid grid_;
  std::vector<eos::AnyEos> eos_;
  // Seeded lazily: mutable so that the const accessors can seed on first use.
  mutable TracerSet tracers_;
  mutable TracerBins bins_;
  mutable int pending_tracers_per_axis_ = 0;  // > 0: tracers_ not yet seeded
  MaterialMap previous_;                      // at the last update_pressure()
  MaterialMap current_;
  MaterialMap next_;  // classify_cells output, swapped with current_
  MaterialStates states_;
  FillScratch fill_scratch_;  // of fill_empty_cells
};

}  // namespace mpfd::fdm
