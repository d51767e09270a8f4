#pragma once
// The nodes a particle talks to and its shape-function weights and gradients
// there: the tensor product of the per-axis weights (shape_functions.hpp),
// with node indices resolved in the sparse grid. Width is 2 for trilinear MPM
// (T (2-7)) and 3 for GIMP; Mask has bit a set when axis a is active, so a 1D
// run has 2 or 3 stencil nodes, 3D has 8 or 27, all known at compile time.

#include <cmath>
#include <cstddef>
#include <type_traits>

#include "common/core/error.hpp"
#include "common/grid/uniform_grid.hpp"
#include "mpm_solver/shape_functions.hpp"
#include "mpm_solver/sparse_grid.hpp"

namespace mpfd::mpm {

template <int Width, int Mask>
struct Stencil {
  static constexpr int kNx = (Mask & 1) ? Width : 1;
  static constexpr int kNy = (Mask & 2) ? Width : 1;
  static constexpr int kNz = (Mask & 4) ? Width : 1;
  static constexpr int kCount = kNx * kNy * kNz;

  grid::Index3 first{};        ///< storage coordinates of the first node
  std::size_t node[kCount];    ///< indices into the node arrays (after the grid is built)
  double weight[kCount];       ///< N_Ip
  double gradient[kCount][3];  ///< N_Ip,j [1/m]
};

/// Geometry shared by every particle of a step.
struct StencilGeometry {
  grid::Vec3 origin{};
  grid::Vec3 inverse_spacing{};
  grid::Index3 offset{};  ///< storage offset per axis (SparseGrid::offset())
};

/// Per-axis weights of a particle at x with GIMP half-width hw (grid units).
template <int Width>
inline void axis_weights(double x, int axis, bool active, const StencilGeometry& g, double hw,
                         AxisWeights<Width>& out) {
  if (!active) {
    out.first = 0;
    out.weight[0] = 1.0;
    out.gradient[0] = 0.0;
    return;
  }
  const double xi = (x - g.origin[axis]) * g.inverse_spacing[axis];
  if constexpr (Width == 2)
    linear_weights(xi, g.inverse_spacing[axis], out);
  else
    gimp_weights(xi, hw, g.inverse_spacing[axis], out);
}

/// First stencil node (storage coordinates) of a particle: what the grid
/// rebuild needs, without the weights.
template <int Width>
inline int first_node(double x, int axis, bool active, const StencilGeometry& g) {
  if (!active) return 0;
  const double xi = (x - g.origin[axis]) * g.inverse_spacing[axis];
  const double base = std::floor(xi);
  const int shift = Width == 3 && xi - base < 0.5 ? 1 : 0;  // as gimp_weights()
  return static_cast<int>(base) - shift + g.offset[axis];
}

/// Fills weights and gradients; with `grid` also the node indices.
template <int Width, int Mask>
inline void compute_stencil(const double x[3], const double half_width[3], const StencilGeometry& g,
                            const SparseGrid& grid, Stencil<Width, Mask>& s) {
  using S = Stencil<Width, Mask>;
  AxisWeights<Width> ax[3];
  axis_weights<Width>(x[0], 0, (Mask & 1) != 0, g, half_width[0], ax[0]);
  axis_weights<Width>(x[1], 1, (Mask & 2) != 0, g, half_width[1], ax[1]);
  axis_weights<Width>(x[2], 2, (Mask & 4) != 0, g, half_width[2], ax[2]);
  for (int a = 0; a < 3; ++a) s.first[a] = ax[a].first + g.offset[a];
  int c = 0;
  for (int k = 0; k < S::kNz; ++k)
    for (int j = 0; j < S::kNy; ++j) {
      const double wyz = ax[1].weight[j] * ax[2].weight[k];
      const double gy = ax[1].gradient[j] * ax[2].weight[k];
      const double gz = ax[1].weight[j] * ax[2].gradient[k];
      for (int i = 0; i < S::kNx; ++i, ++c) {
        s.node[c] = grid.node(s.first[0] + i, s.first[1] + j, s.first[2] + k);
        s.weight[c] = ax[0].weight[i] * wyz;
        s.gradient[c][0] = ax[0].gradient[i] * wyz;
        s.gradient[c][1] = ax[0].weight[i] * gy;
        s.gradient[c][2] = ax[0].weight[i] * gz;
      }
    }
}

/// Calls fn(std::integral_constant<int, Width>, std::integral_constant<int, Mask>)
/// for the run's shape function and active axes, so kernels are compiled per case.
template <class Fn>
void dispatch_stencil(bool gimp, int mask, Fn&& fn) {
  const auto with_mask = [&](auto width) {
    switch (mask) {
      case 1:
        return fn(width, std::integral_constant<int, 1>{});
      case 2:
        return fn(width, std::integral_constant<int, 2>{});
      case 3:
        return fn(width, std::integral_constant<int, 3>{});
      case 4:
        return fn(width, std::integral_constant<int, 4>{});
      case 5:
        return fn(width, std::integral_constant<int, 5>{});
      case 6:
        return fn(width, std::integral_constant<int, 6>{});
      case 7:
        return fn(width, std::integral_constant<int, 7>{});
      default:
        throw Error("mpm: a grid needs at least one axis with more than one cell");
    }
  };
  if (gimp)
    with_mask(std::integral_constant<int, 3>{});
  else
    with_mask(std::integral_constant<int, 2>{});
}

}  // namespace mpfd::mpm
