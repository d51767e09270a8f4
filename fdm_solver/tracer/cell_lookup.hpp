#pragma once
// The cell holding a point, without the optional of UniformGrid::locate():
// tracers are inside the domain by construction, and advection and binning
// must agree on the cell (both use these functions).

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::fdm {

/// Cell along one axis holding the coordinate s, measured in cells from the
/// domain's lower face: floor(s), clamped into [0, n - 1]. s must be finite.
[[nodiscard]] inline int axis_cell(double s, int n) noexcept {
  return std::clamp(static_cast<int>(std::floor(s)), 0, n - 1);
}

/// Coordinate of x along `axis` in cells from the domain's lower face.
[[nodiscard]] inline double cell_coordinate(const grid::UniformGrid& g, int axis,
                                            double x) noexcept {
  return (x - g.origin()[axis]) / g.spacing()[axis];
}

/// Index (grid order, x fastest) of the cell holding the point x.
[[nodiscard]] inline std::size_t cell_holding(const grid::UniformGrid& g,
                                              const grid::Vec3& x) noexcept {
  const grid::Index3& n = g.cells();
  return g.cell_index(axis_cell(cell_coordinate(g, 0, x[0]), n[0]),
                      axis_cell(cell_coordinate(g, 1, x[1]), n[1]),
                      axis_cell(cell_coordinate(g, 2, x[2]), n[2]));
}

}  // namespace mpfd::fdm
