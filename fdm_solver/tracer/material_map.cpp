#include "fdm_solver/tracer/material_map.hpp"

#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"

namespace mpfd::fdm {
namespace {

/// The first two materials with tracers in the cell and how many there are.
struct Present {
  int first = -1;
  int second = -1;
  int count = 0;
};

Present present_materials(const TracerBins& bins, std::size_t cell) {
  Present p;
  for (int r = 0; r < bins.material_count(); ++r) {
    if (bins.count(cell, r) == 0) continue;
    if (p.count == 0) p.first = r;
    if (p.count == 1) p.second = r;
    ++p.count;
  }
  return p;
}

void fail_on_crowded_cell(const grid::UniformGrid& grid, const TracerBins& bins) {
  for (std::size_t c = 0; c < bins.cell_count(); ++c) {
    if (present_materials(bins, c).count < 3) continue;
    const grid::Index3 ijk = grid.cell_of_index(c);
    std::string list;
    for (int r = 0; r < bins.material_count(); ++r)
      if (bins.count(c, r) > 0) list += (list.empty() ? "" : ", ") + std::to_string(r);
    throw Error("tracer classification: cell (" + std::to_string(ijk[0]) + ", " +
                std::to_string(ijk[1]) + ", " + std::to_string(ijk[2]) +
                ") holds tracers of materials " + list +
                "; the mixed-cell closure handles at most 2 materials per cell");
  }
}

void check_layout(const TracerBins& bins, const MaterialMap& map, const char* where) {
  if (bins.cell_count() != map.cell_count() || bins.material_count() != map.material_count)
    throw Error(std::string(where) + ": the tracer bins have " + std::to_string(bins.cell_count()) +
                " cells and " + std::to_string(bins.material_count()) +
                " materials, the material map " + std::to_string(map.cell_count()) + " and " +
                std::to_string(map.material_count));
}

}  // namespace

void check_at_most_two_materials(const grid::UniformGrid& grid, const TracerBins& bins) {
  const std::size_t crowded = parallel_sum(bins.cell_count(), [&](std::size_t c) -> std::size_t {
    return present_materials(bins, c).count >= 3 ? 1 : 0;
  });
  if (crowded > 0) fail_on_crowded_cell(grid, bins);
}

MaterialMap::MaterialMap(std::span<const int> cell_material, int count)
    : material_count(count),
      material(cell_material.begin(), cell_material.end()),
      theta(static_cast<std::size_t>(count) * cell_material.size(), 0.0) {
  for (std::size_t c = 0; c < cell_count(); ++c) {
    if (material[c] < 0 || material[c] >= count)
      throw Error("material map: cell " + std::to_string(c) + " has material " +
                  std::to_string(material[c]) + ", outside [0, " + std::to_string(count) + ")");
    theta[static_cast<std::size_t>(material[c]) * cell_count() + c] = 1.0;
  }
}

void classify_cells(const grid::UniformGrid& grid, const TracerBins& bins, const TracerSet& tracers,
                    const MaterialMap& previous, MaterialMap& next) {
  check_layout(bins, previous, "tracer classification");
  const std::size_t cells = bins.cell_count();
  const int materials = previous.material_count;
  next.material_count = materials;
  next.material.resize(cells);
  next.theta.resize(static_cast<std::size_t>(materials) * cells);
  const auto theta_at = [cells](int r, std::size_t c) {
    return static_cast<std::size_t>(r) * cells + c;
  };
  const std::size_t crowded = parallel_sum(cells, [&](std::size_t c) -> std::size_t {
    const Present p = present_materials(bins, c);
    if (p.count >= 3) return 1;
    if (p.count == 0) {
      next.material[c] = previous.material[c];
      for (int r = 0; r < materials; ++r)
        next.theta[theta_at(r, c)] = previous.theta[theta_at(r, c)];
      return 0;
    }
    for (int r = 0; r < materials; ++r) next.theta[theta_at(r, c)] = 0.0;
    if (p.count == 1) {
      next.material[c] = p.first;
      next.theta[theta_at(p.first, c)] = 1.0;
      return 0;
    }
    double first = 0.0;
    double total = 0.0;
    for (const std::size_t t : bins.tracers_in(c)) {
      first += tracers.material[t] == p.first ? tracers.volume[t] : 0.0;
      total += tracers.volume[t];
    }
    const double theta_first = total > 0.0 ? first / total  // T (3-23)
                                           : static_cast<double>(bins.count(c, p.first)) /
                                                 static_cast<double>(bins.count(c));
    next.material[c] = kMixedCell;
    next.theta[theta_at(p.first, c)] = theta_first;
    next.theta[theta_at(p.second, c)] = 1.0 - theta_first;  // T (3-27)
    return 0;
  });
  if (crowded > 0) fail_on_crowded_cell(grid, bins);
}

void assign_tracer_volumes(const grid::UniformGrid& grid, const TracerBins& bins,
                           const MaterialMap& map, TracerSet& tracers) {
  check_layout(bins, map, "tracer volumes");
  const double cell_volume = grid.cell_volume();
  parallel_for(bins.cell_count(), [&](std::size_t c) {
    const std::size_t n = bins.count(c);
    if (n == 0) return;
    for (const std::size_t t : bins.tracers_in(c)) {
      const int r = tracers.material[t];
      tracers.volume[t] = map.is_mixed(c) ? map.volume_fraction(c, r) * cell_volume /
                                                static_cast<double>(bins.count(c, r))  // T (3-22)
                                          : cell_volume / static_cast<double>(n);      // T (3-21)
    }
  });
}

}  // namespace mpfd::fdm
