#pragma once
// The centres of the n^d equal sub-cells of a cell (n per active axis, 1 on
// an inactive one), where the FDM seeds its tracers (fdm_solver's
// seed_from_materials, T §3.2.2) and the coupler places the tracers it makes.

#include <cstddef>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::coupler::handoff {

/// n^d: the sub-cells of one cell.
[[nodiscard]] inline std::size_t sub_cell_count(const grid::UniformGrid& grid, int n_per_axis) {
  std::size_t count = 1;
  for (int a = 0; a < 3; ++a)
    if (grid.is_active(a)) count *= static_cast<std::size_t>(n_per_axis);
  return count;
}

/// Calls f(x) for each sub-cell centre of `cell`, x fastest (as seed_from_materials).
template <class F>
void for_each_sub_cell_centre(const grid::UniformGrid& grid, const grid::Index3& cell,
                              int n_per_axis, F&& f) {
  grid::Index3 per_axis{};
  for (int a = 0; a < 3; ++a) per_axis[a] = grid.is_active(a) ? n_per_axis : 1;
  for (int k = 0; k < per_axis[2]; ++k)
    for (int j = 0; j < per_axis[1]; ++j)
      for (int i = 0; i < per_axis[0]; ++i) {
        const grid::Index3 sub{i, j, k};
        grid::Vec3 x{};
        for (int a = 0; a < 3; ++a)
          x[a] = grid.origin()[a] + (cell[a] + (sub[a] + 0.5) / per_axis[a]) * grid.spacing()[a];
        f(x);
      }
}

}  // namespace mpfd::coupler::handoff
