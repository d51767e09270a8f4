#include "fdm_solver/tracer/tracker_import.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "fdm_solver/tracer/empty_cell_fill.hpp"

namespace mpfd::fdm {
namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw Error("tracker from imported tracers: " + what);
}

void check_points(const grid::UniformGrid& grid, const TracerSet& points, int material_count) {
  const std::size_t n = points.size();
  for (int a = 0; a < 3; ++a)
    if (points.position[a].size() != n)
      refuse("position component " + std::to_string(a) + " has " +
             std::to_string(points.position[a].size()) + " values for " + std::to_string(n) +
             " tracers");
  const grid::Vec3 lo = grid.origin();
  const grid::Vec3 hi = grid.upper();
  for (std::size_t t = 0; t < n; ++t) {
    if (points.material[t] < 0 || points.material[t] >= material_count)
      refuse("tracer " + std::to_string(t) + " has material " + std::to_string(points.material[t]) +
             ", outside [0, " + std::to_string(material_count) + ")");
    for (int a = 0; a < 3; ++a) {
      const double x = points.position[a][t];
      if (!(x >= lo[a] && x <= hi[a]))  // false for NaN too
        refuse("tracer " + std::to_string(t) + " is at " + std::to_string(x) + " m along axis " +
               std::to_string(a) + ", outside the grid [" + std::to_string(lo[a]) + ", " +
               std::to_string(hi[a]) + "] m");
    }
  }
}

}  // namespace

TrackerState tracker_from_points(const grid::UniformGrid& grid, int material_count,
                                 TracerSet points, std::span<const int> fallback_material,
                                 std::span<const double> density, std::span<const double> energy) {
  const std::size_t cells = grid.cell_count();
  if (fallback_material.size() != cells || density.size() != cells || energy.size() != cells)
    refuse("the grid has " + std::to_string(cells) + " cells; got " +
           std::to_string(fallback_material.size()) + " fallback materials, " +
           std::to_string(density.size()) + " densities and " + std::to_string(energy.size()) +
           " energies");
  check_points(grid, points, material_count);
  // No carried volumes yet: all zero makes classify_cells take theta from the
  // tracer counts, as equal volumes per tracer would.
  points.volume.assign(points.size(), 0.0);
  TracerBins bins;
  bins.rebuild(grid, points, material_count);
  const MaterialMap previous(fallback_material, material_count);
  TrackerState state{std::move(points), {}, {}};
  classify_cells(grid, bins, state.tracers, previous, state.materials);  // T (3-23)
  std::vector<std::size_t> queue;
  queue.reserve(cells);
  fill_empty_cells(grid, bins, state.materials, queue);
  assign_tracer_volumes(grid, bins, state.materials, state.tracers);  // T (3-21), (3-22)
  state.states = MaterialStates(state.materials, density, energy);
  return state;
}

}  // namespace mpfd::fdm
