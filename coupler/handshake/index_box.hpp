#pragma once
// Index boxes of the handshake regions (proto/README.md §4, §11) and the
// vectors the kernels use. A region's values travel in box C order: the last
// axis varies fastest. A box is half-open, [lo, hi) on every axis; cells and
// nodes share the numbering of the coinciding FDM/MPM grids (node i is the
// lower corner of cell i).

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>

namespace mpfd::coupler::handshake {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

template <int Dim>
using Index = std::array<std::int64_t, Dim>;

template <int Dim>
struct IndexBox {
  Index<Dim> lo{};
  Index<Dim> hi{};

  /// Throws mpfd::Error naming `what` unless lo < hi on every axis.
  void check(const char* what) const;

  [[nodiscard]] std::size_t count() const {
    std::size_t n = 1;
    for (int a = 0; a < Dim; ++a) n *= static_cast<std::size_t>(hi[a] - lo[a]);
    return n;
  }
  [[nodiscard]] bool contains(const Index<Dim>& i) const {
    for (int a = 0; a < Dim; ++a)
      if (i[a] < lo[a] || i[a] >= hi[a]) return false;
    return true;
  }
  /// Position of index `i` (inside the box) in C order.
  [[nodiscard]] std::size_t flat(const Index<Dim>& i) const {
    std::size_t n = 0;
    for (int a = 0; a < Dim; ++a)
      n = n * static_cast<std::size_t>(hi[a] - lo[a]) + static_cast<std::size_t>(i[a] - lo[a]);
    return n;
  }
  /// The index at C-order position `n` (< count()).
  [[nodiscard]] Index<Dim> at(std::size_t n) const {
    Index<Dim> i{};
    for (int a = Dim - 1; a >= 0; --a) {
      const auto extent = static_cast<std::size_t>(hi[a] - lo[a]);
      i[a] = lo[a] + static_cast<std::int64_t>(n % extent);
      n /= extent;
    }
    return i;
  }
};

/// The uniform grid the FDM cells and MPM nodes share: cell i spans
/// origin + [i, i + 1) * spacing on each active axis. `cell_volume` V_c is
/// that of the solvers' cells: in 1D and 2D it includes the thickness of the
/// missing axes (common/grid/UniformGrid), so masses are real masses.
template <int Dim>
struct CellGeometry {
  Vec<Dim> origin = Vec<Dim>::Zero();
  Vec<Dim> spacing = Vec<Dim>::Ones();
  double cell_volume = 1;

  /// Throws mpfd::Error unless every spacing and the volume are > 0.
  void check() const;
  /// Area of a cell face normal to `axis`: ΔyΔz of T (4-13) for axis x.
  [[nodiscard]] double face_area(int axis) const { return cell_volume / spacing(axis); }
  [[nodiscard]] Vec<Dim> lower_corner(const Index<Dim>& cell) const {
    Vec<Dim> x;
    for (int a = 0; a < Dim; ++a) x(a) = origin(a) + static_cast<double>(cell[a]) * spacing(a);
    return x;
  }
};

/// The boundary face of the MPM zone (the face between cells k-w and k-w+1 of
/// T Fig. 4.3): normal to `axis`, with the MPM zone on the `side` (+1 or -1)
/// of it. T draws axis 0, side +1; every other face is the same with indices
/// mirrored.
struct ZoneFace {
  int axis = 0;
  int side = 1;
};

/// Throws mpfd::Error unless 0 <= face.axis < Dim and side is +1 or -1.
template <int Dim>
void check_face(const ZoneFace& face);

}  // namespace mpfd::coupler::handshake
