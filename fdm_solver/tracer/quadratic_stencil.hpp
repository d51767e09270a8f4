#pragma once
// Velocity at a tracer from the cell-centre velocities, T (3-9)-(3-12):
// 3-point Lagrange interpolation along each active axis in turn, i.e. the
// tensor product over 3 cells in 1D, 9 in 2D and 27 in 3D:
//   xi = (x - x_c) / dx                                                T (3-9)
//   f(v1, v2, v3, xi) = (v1 - 2 v2 + v3)/2 xi^2 + (v3 - v1)/2 xi + v2  T (3-11)
// with v1, v2, v3 the values at the centres xi = -1, 0, +1. Interpolating
// along x at the three y rows (3-10) of values interpolated along y (3-12) is
// the same tensor product.
// Where this deliberately departs from T:
// * (3-11) is printed with (v3 - v2)/2 as the linear coefficient, which does
//   not reproduce a linear field (f(-1, 0, 1, xi) = xi/2); the Lagrange
//   interpolant the text describes has (v3 - v1)/2.
// * (3-9) scales xi_y by dx too; each axis uses its own spacing here (the
//   same for cubic cells).
// * At the domain edge the stencil is the nearest 3 cells inside the domain
//   (one-sided), so xi is measured from the stencil's centre cell and lies in
//   [-1.5, 1.5]. An active axis with exactly 2 cells interpolates linearly.

#include <array>
#include <span>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/cell_lookup.hpp"

namespace mpfd::fdm {

/// Cell-centre velocity components [m/s] in the grid's cell order. The
/// component along an inactive axis is not read and may be empty.
struct VelocityView {
  std::array<std::span<const double>, 3> component;
};

/// Cells and weights of the interpolation along one axis.
struct AxisStencil {
  std::array<int, 3> cell{};
  std::array<double, 3> weight{};
  int size = 1;
};

/// (3-11) as weights on (v1, v2, v3): f = w1 v1 + w2 v2 + w3 v3.
[[nodiscard]] inline std::array<double, 3> quadratic_weights(double xi) noexcept {
  return {0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)};  // T (3-11)
}

/// Stencil along an axis of n cells at coordinate s (in cells from the
/// domain's lower face).
[[nodiscard]] inline AxisStencil axis_stencil(double s, int n) noexcept {
  if (n == 1) return {{0, 0, 0}, {1.0, 0.0, 0.0}, 1};
  if (n == 2) {
    const double t = s - 0.5;  // from the centre of cell 0, in cells
    return {{0, 1, 0}, {1.0 - t, t, 0.0}, 2};
  }
  const int centre = std::clamp(axis_cell(s, n), 1, n - 2);  // one-sided at the edge
  const double xi = s - (centre + 0.5);                      // T (3-9)
  return {{centre - 1, centre, centre + 1}, quadratic_weights(xi), 3};
}

/// Velocity [m/s] at the point x inside the grid, T (3-10), (3-12); zero
/// along inactive axes.
[[nodiscard]] inline grid::Vec3 interpolate_velocity(const grid::UniformGrid& g,
                                                     const VelocityView& v,
                                                     const grid::Vec3& x) noexcept {
  std::array<AxisStencil, 3> st{};
  for (int a = 0; a < 3; ++a) st[a] = axis_stencil(cell_coordinate(g, a, x[a]), g.cells()[a]);
  grid::Vec3 u{};
  for (int k = 0; k < st[2].size; ++k)
    for (int j = 0; j < st[1].size; ++j)
      for (int i = 0; i < st[0].size; ++i) {
        const double w = st[0].weight[i] * st[1].weight[j] * st[2].weight[k];
        const std::size_t cell = g.cell_index(st[0].cell[i], st[1].cell[j], st[2].cell[k]);
        for (int a = 0; a < 3; ++a)
          if (g.is_active(a)) u[a] += w * v.component[a][cell];
      }
  return u;
}

}  // namespace mpfd::fdm
