#include "fdm_solver/tracer/multi_material_tracker.hpp"

#include <utility>

#include "common/core/error.hpp"
#include "fdm_solver/tracer/empty_cell_fill.hpp"

namespace mpfd::fdm {

MultiMaterialTracker::MultiMaterialTracker(const grid::UniformGrid& grid,
                                           std::vector<eos::AnyEos> materials,
                                           std::span<const double> cell_material,
                                           std::span<const double> density,
                                           std::span<const double> energy, int tracers_per_axis)
    : grid_(grid), eos_(std::move(materials)) {
  if (eos_.empty()) throw Error("multi-material tracker: needs at least one material EOS");
  for (const eos::AnyEos& e : eos_) eos::validate(e);
  const std::vector<int> indices = material_indices(cell_material);
  const int count = static_cast<int>(eos_.size());
  current_ = MaterialMap(indices, count);
  previous_ = current_;
  next_ = current_;
  tracers_ = seed_from_materials(grid_, indices, tracers_per_axis);
  bins_.rebuild(grid_, tracers_, count);
  states_ = MaterialStates(current_, density, energy);
  fill_queue_.reserve(grid_.cell_count());
}

AdvectionReport MultiMaterialTracker::advect(const VelocityView& velocity, double dt,
                                             const TracerBoundaries& faces) {
  const AdvectionReport report = advect_tracers(grid_, velocity, dt, faces, tracers_);
  bins_.rebuild(grid_, tracers_, static_cast<int>(eos_.size()));
  classify_cells(grid_, bins_, tracers_, current_, next_);  // T (3-23)
  fill_empty_cells(grid_, bins_, next_, fill_queue_);
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

}  // namespace mpfd::fdm
