#pragma once
// Cell materials and volume fractions from the tracers, T §3.2.2 (1), §3.3.
// After each advection (T (3-13)) a cell holding tracers of one material is a
// single-material cell of that material; of two materials, a mixed cell with
//   theta_r = sum_{m of r} V_m / sum_m V_m                         T (3-23)
// from the volumes the tracers carry; of none, it keeps its classification.
// Then every tracer gets the volume it carries into the next step:
//   single-material cell:  V_m = V_c / n_b                         T (3-21)
//   mixed cell:            V_m = theta_r V_c / n_br                T (3-22)
// T applies (3-21) only at interface cells (next to a cell of another
// material or a mixed cell); we apply it in every single-material cell: it is
// the same value there, and a tracer that moves diagonally from a bulk cell
// into a mixed cell then carries a defined volume too.

#include <cstddef>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/tracer_bins.hpp"
#include "fdm_solver/tracer/tracer_set.hpp"

namespace mpfd::fdm {

/// MaterialMap::material of a mixed cell.
inline constexpr int kMixedCell = -1;

struct MaterialMap {
  int material_count = 0;
  std::vector<int> material;  ///< per cell: material of a single-material cell, or kMixedCell
  std::vector<double> theta;  ///< theta_r [-] at [r * cells + cell]; sums to 1 in every cell

  MaterialMap() = default;
  /// Every cell single-material with the given material. Throws mpfd::Error
  /// unless every index is in [0, material_count).
  MaterialMap(std::span<const int> cell_material, int material_count);

  [[nodiscard]] std::size_t cell_count() const { return material.size(); }
  [[nodiscard]] bool is_mixed(std::size_t cell) const { return material[cell] == kMixedCell; }
  [[nodiscard]] double volume_fraction(std::size_t cell, int r) const {
    return theta[static_cast<std::size_t>(r) * cell_count() + cell];
  }
  /// theta_r of every cell (a field in the grid's cell order).
  [[nodiscard]] std::span<const double> volume_fractions(int r) const {
    return std::span<const double>(theta).subspan(static_cast<std::size_t>(r) * cell_count(),
                                                  cell_count());
  }
};

/// Throws mpfd::Error naming the first cell that holds tracers of 3 or more
/// materials (the mixed-cell closure handles two), as classify_cells would.
void check_at_most_two_materials(const grid::UniformGrid& grid, const TracerBins& bins);

/// Classifies every cell from the binned tracers, T (3-23); an empty cell
/// copies `previous`. Resizes `next` once, then reuses it. Throws mpfd::Error
/// naming the first cell that holds tracers of 3 or more materials, or if
/// `bins` and `previous` differ in cell or material count.
void classify_cells(const grid::UniformGrid& grid, const TracerBins& bins, const TracerSet& tracers,
                    const MaterialMap& previous, MaterialMap& next);

/// Sets the volume each tracer carries, T (3-21), (3-22), from the
/// classification `map` made from the same `bins` (mpfd::Error if their
/// cell or material counts differ).
void assign_tracer_volumes(const grid::UniformGrid& grid, const TracerBins& bins,
                           const MaterialMap& map, TracerSet& tracers);

}  // namespace mpfd::fdm
