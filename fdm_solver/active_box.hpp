#pragma once
// The disturbed region: a box of cells outside which the state is still,
// bit for bit, what it was at the start. A cell whose whole stencil holds one
// state is left exactly unchanged by a sweep (every flux difference and every
// viscous exchange is exactly zero), so the box starts around every cell that
// differs from a neighbour or from its ghost image, and each sweep along an
// axis grows it along that axis by the sweep's reach (2 cells, see
// euler_solver.cpp). The physical signal (CFL <= 1: at most one cell per
// sweep) stays inside that.

#include <array>

#include "common/config/scene.hpp"
#include "fdm_solver/euler_state.hpp"

namespace mpfd::fdm {

struct ActiveBox {
  std::array<int, 3> lower{0, 0, 0};  ///< first cell per axis
  std::array<int, 3> upper{0, 0, 0};  ///< one past the last cell per axis
  [[nodiscard]] bool empty() const {
    return lower[0] >= upper[0] || lower[1] >= upper[1] || lower[2] >= upper[2];
  }
  [[nodiscard]] long long cells() const {
    return empty() ? 0
                   : 1LL * (upper[0] - lower[0]) * (upper[1] - lower[1]) * (upper[2] - lower[2]);
  }
  /// Grows the box along `axis` by `cells`, within [0, extent).
  void grow(int axis, int cells, int extent);
};

/// The smallest box holding every cell that differs from a neighbour or, at
/// a domain face, from its ghost image under that face's boundary condition.
ActiveBox disturbed_cells(const EulerState& state, const config::Boundaries& boundaries);

/// The box holding every cell.
ActiveBox whole_grid(const grid::UniformGrid& grid);

}  // namespace mpfd::fdm
