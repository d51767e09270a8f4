#include "fdm_solver/tracer/tracker_import.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "fdm_solver/tracer/empty_cell_fill.hpp"

namespace mpfd::fdm {
namespace {

[[noreturn]] void refuse_import(const std::string& what) {
  throw Error("tracker from imported tracers: " + what);
}

void check_points(const grid::UniformGrid& grid, const TracerSet& points, int material_count) {
  const std::size_t n = points.size();
  for (int a = 0; a < 3; ++a)
    if (points.position[a].size() != n)
      refuse_import("position component " + std::to_string(a) + " has " +
                    std::to_string(points.position[a].size()) + " values for " + std::to_string(n) +
                    " tracers");
  const grid::Vec3 lo = grid.origin();
  const grid::Vec3 hi = grid.upper();
  for (std::size_t t = 0; t < n; ++t) {
    if (points.material[t] < 0 || points.material[t] >= material_count)
      refuse_import("tracer " + std::to_string(t) + " has material " +
                    std::to_string(points.material[t]) + ", outside [0, " +
                    std::to_string(material_count) + ")");
    for (int a = 0; a < 3; ++a) {
      const double x = points.position[a][t];
      if (!(x >= lo[a] && x <= hi[a]))  // false for NaN too
        refuse_import("tracer " + std::to_string(t) + " is at " + std::to_string(x) +
                      " m along axis " + std::to_string(a) + ", outside the grid [" +
                      std::to_string(lo[a]) + ", " + std::to_string(hi[a]) + "] m");
    }
  }
}

void check_start(const MaterialStartView& start, std::size_t values) {
  if (start.volume_fraction.empty() && start.density.empty() && start.energy.empty()) return;
  if (start.volume_fraction.size() != values || start.density.size() != values ||
      start.energy.size() != values)
    refuse_import("the material start needs " + std::to_string(values) +
                  " values (materials x cells) of theta, rho_r and e_r; got " +
                  std::to_string(start.volume_fraction.size()) + ", " +
                  std::to_string(start.density.size()) + " and " +
                  std::to_string(start.energy.size()));
}

/// The pair of a mixed cell if `start` holds exactly these two materials there,
/// each with theta_r > 0 and finite rho_r > 0, e_r > 0; else nothing.
std::optional<std::array<int, 2>> start_pair(const MaterialMap& map, const MaterialStartView& start,
                                             std::size_t cell) {
  std::array<int, 2> pair{-1, -1};
  int found = 0;
  for (int r = 0; r < map.material_count; ++r) {
    const std::size_t i = static_cast<std::size_t>(r) * map.cell_count() + cell;
    if (!(map.volume_fraction(cell, r) > 0.0)) {
      if (start.volume_fraction[i] != 0.0) return std::nullopt;  // a material the cell lacks
      continue;
    }
    const bool valid = start.volume_fraction[i] > 0.0 && start.density[i] > 0.0 &&
                       start.energy[i] > 0.0 && std::isfinite(start.volume_fraction[i]) &&
                       std::isfinite(start.density[i]) && std::isfinite(start.energy[i]);
    if (!valid) return std::nullopt;
    if (found < 2) pair[static_cast<std::size_t>(found)] = r;
    ++found;
  }
  if (found != 2) return std::nullopt;
  return pair;
}

}  // namespace

TrackerState tracker_from_points(const grid::UniformGrid& grid, int material_count,
                                 TracerSet points, std::span<const int> fallback_material,
                                 std::span<const double> density, std::span<const double> energy,
                                 const MaterialStartView& start,
                                 const std::function<void()>& accepted) {
  const std::size_t cells = grid.cell_count();
  if (fallback_material.size() != cells || density.size() != cells || energy.size() != cells)
    refuse_import("the grid has " + std::to_string(cells) + " cells; got " +
                  std::to_string(fallback_material.size()) + " fallback materials, " +
                  std::to_string(density.size()) + " densities and " +
                  std::to_string(energy.size()) + " energies");
  check_points(grid, points, material_count);
  check_start(start, static_cast<std::size_t>(material_count) * cells);
  for (std::size_t c = 0; c < cells; ++c)  // as MaterialMap would, but before `accepted`
    if (fallback_material[c] < 0 || fallback_material[c] >= material_count)
      refuse_import("cell " + std::to_string(c) + " has the fallback material " +
                    std::to_string(fallback_material[c]) + ", outside [0, " +
                    std::to_string(material_count) + ")");
  // No carried volumes yet: all zero makes classify_cells take theta from the
  // tracer counts, as equal volumes per tracer would.
  points.volume.assign(points.size(), 0.0);
  TrackerState state{std::move(points), {}, {}};
  MaterialMap& map = state.materials;
  std::vector<std::uint8_t> own_start(start.empty() ? 0 : cells, 0);
  {  // the bins and scratch go before the states are made: the import's memory peak
    TracerBins bins;
    bins.rebuild(grid, state.tracers, material_count);
    check_at_most_two_materials(grid, bins);
    if (accepted) accepted();
    const MaterialMap previous(fallback_material, material_count);
    classify_cells(grid, bins, state.tracers, previous, map);  // T (3-23)
    FillScratch scratch;
    fill_empty_cells(grid, bins, nullptr, 0.0, map, scratch);  // no step before: fill them all
    // Mixed cells with their materials' own start: theta_r from it (the carried
    // volumes below follow), e_r and rho_r after the cell-state default.
    for (std::size_t c = 0; c < own_start.size(); ++c) {
      if (!map.is_mixed(c)) continue;
      const auto pair = start_pair(map, start, c);
      if (!pair) continue;
      const std::size_t a = static_cast<std::size_t>((*pair)[0]) * cells + c;
      const std::size_t b = static_cast<std::size_t>((*pair)[1]) * cells + c;
      const double theta_a =
          start.volume_fraction[a] / (start.volume_fraction[a] + start.volume_fraction[b]);
      if (!(theta_a > 0.0 && theta_a < 1.0)) continue;
      map.theta[a] = theta_a;
      map.theta[b] = 1.0 - theta_a;  // T (3-27)
      own_start[c] = 1;
    }
    assign_tracer_volumes(grid, bins, map, state.tracers);  // T (3-21), (3-22)
  }
  state.states = MaterialStates(map, density, energy);
  for (std::size_t c = 0; c < own_start.size(); ++c) {
    if (own_start[c] == 0) continue;
    for (int r = 0; r < material_count; ++r) {
      const std::size_t i = state.states.at(r, c);
      if (map.volume_fraction(c, r) <= 0.0) continue;
      state.states.energy[i] = start.energy[i];
      state.states.density[i] = start.density[i];
    }
  }
  return state;
}

}  // namespace mpfd::fdm
