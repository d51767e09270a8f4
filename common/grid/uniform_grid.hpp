#pragma once
// Uniform Cartesian grid shared by the FDM cells and the MPM background grid.
// 1D, 2D and 3D use the same code: an unused axis has one cell, its spacing is
// the domain's thickness along it (so cell volumes stay physical), and it has
// one node layer (shape functions are constant along it).
// Cells and nodes are numbered x fastest: index = i + nx (j + ny k), so an
// x-pencil is contiguous in memory.

#include <array>
#include <cstddef>
#include <optional>

namespace mpfd::grid {

using Vec3 = std::array<double, 3>;
using Index3 = std::array<int, 3>;

/// A point located in the grid: the cell holding it and its local
/// coordinates in that cell, each in [0, 1).
struct CellLocation {
  Index3 cell;
  Vec3 local;
};

class UniformGrid {
 public:
  /// Throws mpfd::Error unless every cell count is >= 1 and every spacing > 0.
  UniformGrid(Vec3 origin, Vec3 spacing, Index3 cells);
  /// The grid of `cells` equal cells filling the box [lower, upper].
  static UniformGrid from_bounds(Vec3 lower, Vec3 upper, Index3 cells);

  [[nodiscard]] const Vec3& origin() const { return origin_; }
  [[nodiscard]] const Vec3& spacing() const { return spacing_; }
  [[nodiscard]] const Index3& cells() const { return cells_; }
  [[nodiscard]] Vec3 upper() const;
  /// Number of axes with more than one cell (1, 2 or 3).
  [[nodiscard]] int dimension() const;
  [[nodiscard]] bool is_active(int axis) const { return cells_[axis] > 1; }

  [[nodiscard]] std::size_t cell_count() const;
  [[nodiscard]] Index3 nodes() const;
  [[nodiscard]] std::size_t node_count() const;
  [[nodiscard]] double cell_volume() const { return spacing_[0] * spacing_[1] * spacing_[2]; }

  [[nodiscard]] std::size_t cell_index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(cells_[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(cells_[1]) * k);
  }
  [[nodiscard]] std::size_t cell_index(const Index3& c) const {
    return cell_index(c[0], c[1], c[2]);
  }
  [[nodiscard]] Index3 cell_of_index(std::size_t index) const;
  [[nodiscard]] std::size_t node_index(const Index3& n) const;
  [[nodiscard]] Index3 node_of_index(std::size_t index) const;

  [[nodiscard]] Vec3 cell_center(const Index3& c) const;
  /// Position of a node; on an inactive axis the single node layer sits at
  /// the cell centre.
  [[nodiscard]] Vec3 node_position(const Index3& n) const;

  /// True if the point lies in [origin, upper) on every axis.
  [[nodiscard]] bool contains(const Vec3& point) const;
  /// The cell holding the point, or nothing if it is outside the grid.
  [[nodiscard]] std::optional<CellLocation> locate(const Vec3& point) const;

 private:
  Vec3 origin_;
  Vec3 spacing_;
  Index3 cells_;
};

}  // namespace mpfd::grid
