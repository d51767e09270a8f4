#include "fdm_solver/active_box.hpp"

#include <algorithm>

namespace mpfd::fdm {
namespace {

bool same_state(const EulerState& s, std::size_t a, std::size_t b) {
  for (const auto& v : s.u)
    if (v[a] != v[b]) return false;
  return s.material[a] == s.material[b];
}

/// True if the cell differs from its mirror image (normal momentum reversed).
bool moves_through_wall(const EulerState& s, std::size_t cell, int axis) {
  return s.u[kMomentumX + static_cast<std::size_t>(axis)][cell] != 0.0;
}

}  // namespace

void ActiveBox::grow(int axis, int cells, int extent) {
  if (empty()) return;
  lower[axis] = std::max(0, lower[axis] - cells);
  upper[axis] = std::min(extent, upper[axis] + cells);
}

ActiveBox whole_grid(const grid::UniformGrid& grid) {
  return {{0, 0, 0}, {grid.cells()[0], grid.cells()[1], grid.cells()[2]}};
}

ActiveBox disturbed_cells(const EulerState& state, const config::Boundaries& boundaries) {
  const auto& g = state.grid;
  const auto n = g.cells();
  ActiveBox box{{n[0], n[1], n[2]}, {0, 0, 0}};
  const auto mark = [&box](const grid::Index3& c) {
    for (int a = 0; a < 3; ++a) {
      box.lower[a] = std::min(box.lower[a], c[a]);
      box.upper[a] = std::max(box.upper[a], c[a] + 1);
    }
  };
  for (std::size_t index = 0; index < g.cell_count(); ++index) {
    const grid::Index3 c = g.cell_of_index(index);
    for (int a = 0; a < 3; ++a) {
      if (!g.is_active(a)) continue;
      if (c[a] + 1 < n[a]) {
        grid::Index3 next = c;
        ++next[a];
        if (!same_state(state, index, g.cell_index(next))) {
          mark(c);
          mark(next);
        }
      }
      const auto lower = static_cast<config::Face>(2 * a);
      const auto upper = static_cast<config::Face>(2 * a + 1);
      const bool at_lower_wall = c[a] == 0 && boundaries[lower] != config::BoundaryKind::outflow;
      const bool at_upper_wall =
          c[a] == n[a] - 1 && boundaries[upper] != config::BoundaryKind::outflow;
      if ((at_lower_wall || at_upper_wall) && moves_through_wall(state, index, a)) mark(c);
    }
  }
  return box;
}

}  // namespace mpfd::fdm
