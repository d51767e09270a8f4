#include "fdm_solver/tracer/multi_material_tracker.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "common/core/error.hpp"
#include "fdm_solver/tracer/empty_cell_fill.hpp"

namespace mpfd::fdm {
namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw Error("multi-material tracker restore: " + what);
}

void check_size(const char* name, std::size_t size, std::size_t expected, const char* of) {
  if (size != expected)
    refuse(std::string(name) + " has " + std::to_string(size) + " values; expected " +
           std::to_string(expected) + " (" + of + ")");
}

void check_tracers(const grid::UniformGrid& grid, const TracerSet& tracers, int materials) {
  const std::size_t n = tracers.size();
  for (int a = 0; a < 3; ++a)
    check_size("a tracer position component", tracers.position[a].size(), n, "one per tracer");
  check_size("the tracer volumes", tracers.volume.size(), n, "one per tracer");
  const grid::Vec3 lo = grid.origin();
  const grid::Vec3 hi = grid.upper();
  for (std::size_t t = 0; t < n; ++t) {
    if (tracers.material[t] < 0 || tracers.material[t] >= materials)
      refuse("tracer " + std::to_string(t) + " has material " +
             std::to_string(tracers.material[t]) + ", outside [0, " + std::to_string(materials) +
             ")");
    for (int a = 0; a < 3; ++a) {
      const double x = tracers.position[a][t];
      if (!(x >= lo[a] && x <= hi[a]))  // false for NaN too
        refuse("tracer " + std::to_string(t) + " is at " + std::to_string(x) + " m along axis " +
               std::to_string(a) + ", outside the grid [" + std::to_string(lo[a]) + ", " +
               std::to_string(hi[a]) + "] m");
    }
    if (!std::isfinite(tracers.volume[t]) || tracers.volume[t] < 0.0)
      refuse("tracer " + std::to_string(t) + " carries the volume " +
             std::to_string(tracers.volume[t]) + " m^3; it must be finite and >= 0");
  }
}

void check_materials(const MaterialMap& map, std::size_t cells, int materials) {
  if (map.material_count != materials)
    refuse("the material map has " + std::to_string(map.material_count) +
           " materials; the tracker " + std::to_string(materials));
  check_size("the cell materials", map.material.size(), cells, "one per cell");
  check_size("theta", map.theta.size(), static_cast<std::size_t>(materials) * cells,
             "materials x cells");
  for (std::size_t c = 0; c < cells; ++c)
    if (map.material[c] != kMixedCell && (map.material[c] < 0 || map.material[c] >= materials))
      refuse("cell " + std::to_string(c) + " has material " + std::to_string(map.material[c]) +
             ", neither mixed (" + std::to_string(kMixedCell) + ") nor in [0, " +
             std::to_string(materials) + ")");
}

void check_states(const MaterialStates& states, std::size_t cells, int materials) {
  const std::size_t per_material = static_cast<std::size_t>(materials) * cells;
  check_size("the material states' cell count", states.cell_count, cells, "the grid's cells");
  check_size("e_r", states.energy.size(), per_material, "materials x cells");
  check_size("rho_r", states.density.size(), per_material, "materials x cells");
  check_size("e_c", states.cell_energy.size(), cells, "one per cell");
  check_size("the closure status", states.status.size(), cells, "one per cell");
  for (std::size_t c = 0; c < cells; ++c)
    if (states.status[c] > ClosureStatus::fallback)
      refuse("cell " + std::to_string(c) + " has closure status " +
             std::to_string(static_cast<int>(states.status[c])) + ", not one of 0-3");
}

}  // namespace

MultiMaterialTracker::MultiMaterialTracker(const grid::UniformGrid& grid,
                                           std::vector<eos::AnyEos> materials,
                                           std::span<const double> cell_material,
                                           std::span<const double> density,
                                           std::span<const double> energy, int tracers_per_axis)
    : grid_(grid), eos_(std::move(materials)) {
  if (eos_.empty()) throw Error("multi-material tracker: needs at least one material EOS");
  for (const eos::AnyEos& e : eos_) eos::validate(e);
  if (tracers_per_axis < 1)
    throw Error("tracers: tracers per cell and axis must be >= 1, got " +
                std::to_string(tracers_per_axis));
  const std::vector<int> indices = material_indices(cell_material);
  if (indices.size() != grid_.cell_count())
    throw Error("tracers: the cell material array has " + std::to_string(indices.size()) +
                " entries, the grid " + std::to_string(grid_.cell_count()) + " cells");
  const int count = static_cast<int>(eos_.size());
  current_ = MaterialMap(indices, count);
  previous_ = current_;
  next_ = current_;
  pending_tracers_per_axis_ = tracers_per_axis;
  states_ = MaterialStates(current_, density, energy);
  fill_scratch_.size_for(grid_.cell_count());
}

MultiMaterialTracker::MultiMaterialTracker(const grid::UniformGrid& grid,
                                           std::vector<eos::AnyEos> materials, TrackerState state)
    : grid_(grid), eos_(std::move(materials)) {
  if (eos_.empty()) throw Error("multi-material tracker: needs at least one material EOS");
  for (const eos::AnyEos& e : eos_) eos::validate(e);
  restore(std::move(state));
  fill_scratch_.size_for(grid_.cell_count());
}

void MultiMaterialTracker::seed_if_pending() const {
  if (pending_tracers_per_axis_ == 0) return;
  // current_ is still the constructor's classification: only advect() changes
  // it, and advect() seeds first.
  tracers_ = seed_from_materials(grid_, current_.material, pending_tracers_per_axis_);
  bins_.rebuild(grid_, tracers_, static_cast<int>(eos_.size()));
  pending_tracers_per_axis_ = 0;
}

const TracerSet& MultiMaterialTracker::tracers() const {
  seed_if_pending();
  return tracers_;
}

const TracerBins& MultiMaterialTracker::bins() const {
  seed_if_pending();
  return bins_;
}

AdvectionReport MultiMaterialTracker::advect(const VelocityView& velocity, double dt,
                                             const TracerBoundaries& faces) {
  seed_if_pending();
  const AdvectionReport report = advect_tracers(grid_, velocity, dt, faces, tracers_);
  bins_.rebuild(grid_, tracers_, static_cast<int>(eos_.size()));
  classify_cells(grid_, bins_, tracers_, current_, next_);  // T (3-23)
  fill_empty_cells(grid_, bins_, &current_, report.max_cells_moved, next_, fill_scratch_);
  std::swap(current_, next_);
  assign_tracer_volumes(grid_, bins_, current_, tracers_);  // T (3-21), (3-22)
  return report;
}

ClosureReport MultiMaterialTracker::update_pressure(std::span<const double> density,
                                                    std::span<const double> energy,
                                                    std::span<double> pressure) {
  const ClosureReport report =
      update_cell_pressure(grid_, eos_, previous_, current_, density, energy, states_, pressure);
  previous_ = current_;  // same sizes: no allocation
  return report;
}

void MultiMaterialTracker::restore(TrackerState state) {
  const int materials = static_cast<int>(eos_.size());
  const std::size_t cells = grid_.cell_count();
  check_tracers(grid_, state.tracers, materials);
  check_materials(state.materials, cells, materials);
  check_states(state.states, cells, materials);
  tracers_ = std::move(state.tracers);
  pending_tracers_per_axis_ = 0;
  current_ = std::move(state.materials);
  previous_ = current_;  // as after update_pressure()
  next_ = current_;      // scratch of classify_cells, of the same sizes
  states_ = std::move(state.states);
  bins_.rebuild(grid_, tracers_, materials);  // from positions and materials alone
}

}  // namespace mpfd::fdm
