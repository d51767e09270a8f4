#pragma once
// The nodes a particle talks to and its shape-function weights and gradients
// there: the tensor product of the per-axis weights (shape_functions.hpp),
// with node indices resolved in the sparse grid. Width is 2 for trilinear MPM
// (T (2-7)) and 3 for GIMP; Mask has bit a set when axis a is active, so a 1D
// run has 2 or 3 stencil nodes, 3D has 8 or 27, all known at compile time.

#include <cmath>
#include <cstddef>
#include <cstdint>
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
  if constexpr (Width == 3)  // as gimp_weights(): around the nearest node
    return static_cast<int>(std::floor(xi + 0.5)) - 1 + g.offset[axis];
  else
    return static_cast<int>(std::floor(xi)) + g.offset[axis];
}

/// Fills node indices, weights and gradients. Always inlined: a kernel that
/// reads only the weights lets the compiler drop the gradients.
template <int Width, int Mask>
[[gnu::always_inline]] inline void compute_stencil(const double x[3], const double half_width[3],
                                                   const StencilGeometry& g, const SparseGrid& grid,
                                                   Stencil<Width, Mask>& s) {
  using S = Stencil<Width, Mask>;
  AxisWeights<Width> ax[3];
  axis_weights<Width>(x[0], 0, (Mask & 1) != 0, g, half_width[0], ax[0]);
  axis_weights<Width>(x[1], 1, (Mask & 2) != 0, g, half_width[1], ax[1]);
  axis_weights<Width>(x[2], 2, (Mask & 4) != 0, g, half_width[2], ax[2]);
  for (int a = 0; a < 3; ++a) s.first[a] = ax[a].first + g.offset[a];
  // The stencil spans at most two blocks per axis: look their slots up once.
  constexpr int kShift = SparseGrid::kBlockShift;
  constexpr int kMask[3] = {(Mask & 1) ? (1 << kShift) - 1 : 0, (Mask & 2) ? (1 << kShift) - 1 : 0,
                            (Mask & 4) ? (1 << kShift) - 1 : 0};
  constexpr int kDimX = kMask[0] + 1, kDimY = kMask[1] + 1;
  constexpr int kShiftOf[3] = {(Mask & 1) ? kShift : 0, (Mask & 2) ? kShift : 0,
                               (Mask & 4) ? kShift : 0};
  int block[3], local[3], span[3];
  for (int a = 0; a < 3; ++a) {
    block[a] = s.first[a] >> kShiftOf[a];
    local[a] = s.first[a] & kMask[a];
    const int width = (Mask >> a) & 1 ? Width : 1;
    span[a] = local[a] + width - 1 > kMask[a] ? 2 : 1;
  }
  std::int32_t slots[2][2][2] = {};
  for (int dk = 0; dk < span[2]; ++dk)
    for (int dj = 0; dj < span[1]; ++dj)
      for (int di = 0; di < span[0]; ++di)
        slots[dk][dj][di] = grid.slot(block[0] + di, block[1] + dj, block[2] + dk);
  const auto block_nodes = static_cast<std::size_t>(grid.block_nodes());
  int c = 0;
  for (int k = 0; k < S::kNz; ++k) {
    const int lz = local[2] + k;
    const int bz = lz >> kShiftOf[2];
    for (int j = 0; j < S::kNy; ++j) {
      const int ly = local[1] + j;
      const int by = ly >> kShiftOf[1];
      const double wyz = ax[1].weight[j] * ax[2].weight[k];
      const double gy = ax[1].gradient[j] * ax[2].weight[k];
      const double gz = ax[1].weight[j] * ax[2].gradient[k];
      const int offset_yz = kDimX * ((ly & kMask[1]) + kDimY * (lz & kMask[2]));
      for (int i = 0; i < S::kNx; ++i, ++c) {
        const int lx = local[0] + i;
        s.node[c] = static_cast<std::size_t>(slots[bz][by][lx >> kShiftOf[0]]) * block_nodes +
                    static_cast<std::size_t>((lx & kMask[0]) + offset_yz);
        s.weight[c] = ax[0].weight[i] * wyz;
        s.gradient[c][0] = ax[0].gradient[i] * wyz;
        s.gradient[c][1] = ax[0].weight[i] * gy;
        s.gradient[c][2] = ax[0].weight[i] * gz;
      }
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
