#pragma once
// The 2^d corner nodes of a cell on grid::UniformGrid (an inactive axis has
// one node layer and a constant shape function) and the linear shape
// functions N_I(x) = prod_a (1 - |x_a - x_Ia| / h_a) of T (2-7).

#include <array>
#include <cstddef>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::coupler::handoff {

/// Number of corner nodes of a cell: 2^d.
[[nodiscard]] inline int corner_count(const grid::UniformGrid& grid) {
  return 1 << grid.dimension();
}

/// Node index (grid::node_index order) of corner `corner` (bit a = upper
/// node along the a-th active axis) of cell `cell`.
[[nodiscard]] inline grid::Index3 corner_node(const grid::UniformGrid& grid,
                                              const grid::Index3& cell, int corner) {
  grid::Index3 node{0, 0, 0};
  int bit = 0;
  for (int a = 0; a < 3; ++a) {
    if (!grid.is_active(a)) continue;
    node[a] = cell[a] + ((corner >> bit) & 1);
    ++bit;
  }
  return node;
}

/// N_I at local cell coordinates `local` (each in [0, 1)) for corner `corner`.
[[nodiscard]] inline double corner_weight(const grid::UniformGrid& grid, const grid::Vec3& local,
                                          int corner) {
  double w = 1.0;
  int bit = 0;
  for (int a = 0; a < 3; ++a) {
    if (!grid.is_active(a)) continue;
    w *= ((corner >> bit) & 1) ? local[a] : 1.0 - local[a];
    ++bit;
  }
  return w;
}

/// Share of node `node`'s quantity that goes to each adjacent cell: N_Ic of
/// T (3-3) = 1/2 per active axis at the cell centre, renormalised to 1 on a
/// boundary node layer (which has one adjacent cell), so the shares of every
/// node sum to 1 and the transfer conserves exactly.
[[nodiscard]] inline double node_to_cell_share(const grid::UniformGrid& grid,
                                               const grid::Index3& node) {
  double share = 1.0;
  for (int a = 0; a < 3; ++a)
    if (grid.is_active(a) && node[a] > 0 && node[a] < grid.cells()[a]) share *= 0.5;
  return share;
}

}  // namespace mpfd::coupler::handoff
