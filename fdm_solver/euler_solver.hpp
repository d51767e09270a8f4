#pragma once
// The FDM Euler solver of T §2.2: Strang-split sweeps (2-52), each a
// two-step Lax-Wendroff update with adaptive artificial viscosity
// (sweep_kernel.hpp), on the disturbed region only (active_box.hpp).
// Owns the state; knows nothing of output, coupling or the command line.

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "common/config/scene.hpp"
#include "common/eos/any_eos.hpp"
#include "fdm_solver/active_box.hpp"
#include "fdm_solver/euler_state.hpp"
#include "fdm_solver/pencil.hpp"
#include "fdm_solver/quiet_face_flux.hpp"
#include "fdm_solver/tracer/multi_material_tracker.hpp"
#include "fdm_solver/tracer/tracker_import.hpp"

namespace mpfd::fdm {

struct SolverOptions {
  double cfl = 0.5;          ///< Courant number of each 1D sweep, (|u| + c) dt_sweep / dx
  double viscosity = 1.0;    ///< kappa, scale of the artificial viscosity (2-58)
  int switch_power = 1;      ///< p of the switch theta^p, T (2-57); 1 is the thesis
  bool skip_quiet = true;    ///< update only the disturbed region (bitwise the same result)
  int tracers_per_axis = 2;  ///< massless tracers per cell and active axis (multi-material)

  /// The scene's `time` CFL and `solver.fdm` options; skip_quiet on.
  static SolverOptions from_scene(const config::Scene& scene);
};

/// Conserved totals over the domain: mass [kg], momentum x/y/z [kg m/s], energy [J].
using Totals = std::array<double, kVariables>;
/// Per domain face (config::Face order), per boundary cell: [cell * kVariables + v].
using FaceOutflow = std::array<std::vector<double>, 6>;

class EulerSolver {
 public:
  /// The state is the scene's initial condition on its domain grid.
  EulerSolver(const config::Scene& scene, SolverOptions options);

  /// The largest stable step [s]: each of the split half-step sweeps keeps
  /// (|u| + c) (dt/2) / dx <= cfl on every cell and active axis.
  [[nodiscard]] double stable_dt() const;
  /// stable_dt(), shortened so that `target` [s] is reached exactly and no
  /// sliver of a step is left before it (the last two steps split the rest).
  [[nodiscard]] double step_toward(double target) const;
  /// Advances by step_toward(end) until time() == end.
  void advance_to(double end);
  /// One step of (2-52): sweeps z y x x y z, each over dt/2. Throws
  /// mpfd::Error naming the cell, position, time and values if a density or
  /// pressure stops being positive and finite.
  void advance(double dt);

  [[nodiscard]] double time() const { return time_; }
  [[nodiscard]] std::int64_t steps() const { return steps_; }
  [[nodiscard]] const EulerState& state() const { return state_; }
  /// Write access for data from outside (coupling, restore): the cells of
  /// `region` join the disturbed region, so that skipping still cells stays
  /// exact. Write only inside `region`.
  [[nodiscard]] EulerState& state_for_update(const ActiveBox& region);
  [[nodiscard]] const std::vector<eos::AnyEos>& materials() const { return eos_; }
  [[nodiscard]] const ActiveBox& active_box() const { return box_; }
  /// Cell updates done so far (one = one cell advanced by one whole step of
  /// (2-52); skipped still cells do not count), for throughput figures.
  [[nodiscard]] double cell_updates() const { return cell_updates_; }

  /// The tracers and volume fractions, or null in a one-material scene.
  [[nodiscard]] const MultiMaterialTracker* tracker() const {
    return tracker_ ? &*tracker_ : nullptr;
  }
  /// Mixed cells and closure fallbacks at the end of the last step.
  [[nodiscard]] const ClosureReport& last_closure() const { return closure_; }

  /// Continues from a checkpoint: replaces the state, the clock (time,
  /// steps), the accumulated boundary outflow (its sums and each face's per
  /// cell, as face_outflow(); the watched crossing restarts from zero) and the
  /// tracker's state: a multi-material solver must be given one, and a solver
  /// of one material given one becomes multi-material, as import_state made
  /// the solver that saved it (saved from tracker()).
  /// The disturbed box becomes the whole grid, since which cells are still is
  /// not part of a checkpoint: exactness over speed after a restore (a still
  /// cell is advanced to the same bits as a skipped one). `state` must be on
  /// this solver's grid. Throws mpfd::Error otherwise, before changing anything.
  void restore(const EulerState& state, double time, std::int64_t steps, const Totals& outflow,
               const FaceOutflow& face_outflow, std::optional<TrackerState> tracker = std::nullopt);

  /// Takes cells and tracers from outside (an AFDMP handoff, proto/README.md
  /// §15): the conserved fields of `cells` (on this solver's grid; its
  /// material and mixture fields are ignored) replace the state's; `tracers`
  /// (positions and materials; volumes ignored) replace the tracker's, and a
  /// one-material solver becomes multi-material; without them a tracker is
  /// rebuilt from the tracers it holds. The tracker starts as
  /// tracker_from_points() builds it (each material of a cell at the cell's
  /// state, or in a mixed cell at its own state from `start` where that holds
  /// one), then the closure gives the pressures. Clock and outflow carry on;
  /// the disturbed box becomes the cells the new state disturbs (so quiet
  /// cells stay skipped). Throws mpfd::Error before changing anything.
  /// `cells` is taken (moved from, it becomes the state) and the old tracker
  /// is released before the new one is built from the tracker state: a
  /// whole-grid import does not hold two trackers and two states at once
  /// (so running out of memory while the new one is built leaves none).
  void import_state(EulerState cells, std::optional<TracerSet> tracers,
                    const MaterialStartView& start = {});

  [[nodiscard]] Totals totals() const;
  /// What has left through the domain faces since the start (momentum: the
  /// impulse of walls included).
  [[nodiscard]] const Totals& outflow() const { return outflow_; }
  /// outflow() per boundary cell of domain face `face` (config::Face order;
  /// cells numbered as in QuietFaceFlux), [cell * kVariables + v], since the
  /// start.
  [[nodiscard]] const std::vector<double>& face_outflow(int face) const {
    return face_outflow_[static_cast<std::size_t>(face)];
  }
  [[nodiscard]] const FaceOutflow& face_outflow() const { return face_outflow_; }

  /// From now on counts what crosses the faces normal to `axis` between cells
  /// index - 1 and index (0 < index < cells along axis) toward +axis: a
  /// coupling face. Those cells join the disturbed region for good, so that
  /// every sweep reports that face. Throws mpfd::Error for a face not inside.
  void watch_face(int axis, int index);
  /// What crossed the watched face since the last clear, per line (numbered as
  /// QuietFaceFlux numbers a face's cells), [line * kVariables + v]: mass
  /// [kg], momentum x/y/z [kg m/s], total energy [J]. Empty if none is watched.
  [[nodiscard]] const std::vector<double>& watched_crossing() const { return watched_crossing_; }
  void clear_watched_crossing();

 private:
  /// One sweep, or two in a row along `axis` (twice); the last of a step
  /// also returns the smallest crossing time of the cells it updated (+inf
  /// if none).
  double sweep(int axis, double dt, bool twice, bool last_of_step);
  /// Adds what crossed the faces normal to `axis` at still boundary cells.
  void count_quiet_faces(int axis, double dt, bool lower_updated, bool upper_updated);
  /// min of dx_a / (|u_a| + c) over active axes a and the cells [from, to)
  /// of the x-line that starts at cell `start` [s].
  [[nodiscard]] double line_limit(std::size_t start, int from, int to) const;
  /// The same minimum over the cells outside the disturbed box (still, so
  /// per line from the start where a whole line is outside) [s].
  [[nodiscard]] double still_limit() const;
  /// The minimum over the whole grid, from the present state [s].
  [[nodiscard]] double grid_limit() const;
  /// Cell pressures from the tracer closure; mixed cells get their fitted EOS.
  void update_materials();
  /// Allocates what only a multi-material solver uses (mixture fits, scratch).
  void allocate_multi_material();
  /// The disturbed box, the fluxes of still boundary cells and the limits of
  /// still lines, from the present state (at the start and after an import).
  void find_still_cells();
  /// Throws mpfd::Error unless `state`'s conserved fields fit this grid.
  void check_grid_of(const EulerState& state, const char* what) const;

  EulerState state_;
  config::Boundaries boundaries_;
  SolverOptions options_;
  std::vector<eos::AnyEos> eos_;
  ActiveBox box_;
  std::vector<Pencil> pencils_;           // one per thread
  std::vector<double> still_line_limit_;  // min dx/(|u|+c) of each x-line at the start/import
  // min dx/(|u|+c) over the grid after the last step, found in its last
  // sweep (after the materials' update with tracers); empty where unknown
  // (before a step, after writes from outside).
  std::optional<double> limit_after_step_;
  std::optional<std::uint8_t> only_material_;  // of every cell, this step, if one
  QuietFaceFlux quiet_flux_;                   // through faces of still boundary cells
  std::optional<MultiMaterialTracker> tracker_;
  TracerBoundaries tracer_faces_{};
  std::array<std::vector<double>, 3> velocity_;  // scratch for tracer advection
  std::vector<double> energy_, pressure_;        // scratch for the closure
  ClosureReport closure_;
  Totals outflow_{};
  FaceOutflow face_outflow_;                   // see face_outflow()
  int watched_axis_ = -1, watched_index_ = 0;  // see watch_face()
  std::vector<double> watched_crossing_;
  double time_ = 0.0;
  std::int64_t steps_ = 0;
  double cell_updates_ = 0.0;
};

}  // namespace mpfd::fdm
