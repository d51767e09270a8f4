#include "common/grid/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::grid {
namespace {

constexpr const char* kAxisName[3] = {"x", "y", "z"};

}  // namespace

UniformGrid::UniformGrid(Vec3 origin, Vec3 spacing, Index3 cells)
    : origin_(origin), spacing_(spacing), cells_(cells) {
  for (int a = 0; a < 3; ++a) {
    if (cells_[a] < 1)
      throw Error(std::string("grid: cell count along ") + kAxisName[a] + " must be >= 1, got " +
                  std::to_string(cells_[a]));
    if (!(spacing_[a] > 0.0) || !std::isfinite(spacing_[a]))
      throw Error(std::string("grid: spacing along ") + kAxisName[a] +
                  " must be a finite number > 0 m, got " + std::to_string(spacing_[a]));
    if (!std::isfinite(origin_[a]))
      throw Error(std::string("grid: origin along ") + kAxisName[a] + " must be finite");
  }
}

UniformGrid UniformGrid::from_bounds(Vec3 lower, Vec3 upper, Index3 cells) {
  Vec3 spacing{};
  for (int a = 0; a < 3; ++a) {
    if (!(upper[a] > lower[a]))
      throw Error(std::string("grid: upper bound along ") + kAxisName[a] + " (" +
                  std::to_string(upper[a]) + " m) must exceed the lower bound (" +
                  std::to_string(lower[a]) + " m)");
    if (cells[a] < 1)
      throw Error(std::string("grid: cell count along ") + kAxisName[a] + " must be >= 1, got " +
                  std::to_string(cells[a]));
    spacing[a] = (upper[a] - lower[a]) / cells[a];
  }
  return UniformGrid(lower, spacing, cells);
}

Vec3 UniformGrid::upper() const {
  return {origin_[0] + spacing_[0] * cells_[0], origin_[1] + spacing_[1] * cells_[1],
          origin_[2] + spacing_[2] * cells_[2]};
}

int UniformGrid::dimension() const {
  return int(is_active(0)) + int(is_active(1)) + int(is_active(2));
}

std::size_t UniformGrid::cell_count() const {
  return static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
}

Index3 UniformGrid::nodes() const {
  Index3 n{};
  for (int a = 0; a < 3; ++a) n[a] = is_active(a) ? cells_[a] + 1 : 1;
  return n;
}

std::size_t UniformGrid::node_count() const {
  const Index3 n = nodes();
  return static_cast<std::size_t>(n[0]) * n[1] * n[2];
}

Index3 UniformGrid::cell_of_index(std::size_t index) const {
  const auto nx = static_cast<std::size_t>(cells_[0]);
  const auto ny = static_cast<std::size_t>(cells_[1]);
  return {static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
          static_cast<int>(index / (nx * ny))};
}

std::size_t UniformGrid::node_index(const Index3& n) const {
  const Index3 count = nodes();
  return static_cast<std::size_t>(n[0]) +
         static_cast<std::size_t>(count[0]) *
             (static_cast<std::size_t>(n[1]) + static_cast<std::size_t>(count[1]) * n[2]);
}

Index3 UniformGrid::node_of_index(std::size_t index) const {
  const Index3 count = nodes();
  const auto nx = static_cast<std::size_t>(count[0]);
  const auto ny = static_cast<std::size_t>(count[1]);
  return {static_cast<int>(index % nx), static_cast<int>((index / nx) % ny),
          static_cast<int>(index / (nx * ny))};
}

Vec3 UniformGrid::cell_center(const Index3& c) const {
  Vec3 x{};
  for (int a = 0; a < 3; ++a) x[a] = origin_[a] + (c[a] + 0.5) * spacing_[a];
  return x;
}

Vec3 UniformGrid::node_position(const Index3& n) const {
  Vec3 x{};
  for (int a = 0; a < 3; ++a)
    x[a] = is_active(a) ? origin_[a] + n[a] * spacing_[a] : origin_[a] + 0.5 * spacing_[a];
  return x;
}

bool UniformGrid::contains(const Vec3& point) const {
  const Vec3 hi = upper();
  for (int a = 0; a < 3; ++a)
    if (!(point[a] >= origin_[a] && point[a] < hi[a])) return false;
  return true;
}

std::optional<CellLocation> UniformGrid::locate(const Vec3& point) const {
  if (!contains(point)) return std::nullopt;
  CellLocation where{};
  for (int a = 0; a < 3; ++a) {
    const double s = (point[a] - origin_[a]) / spacing_[a];
    // Clamp: rounding can put a point just below upper() at s == cells.
    const int c = std::min(static_cast<int>(std::floor(s)), cells_[a] - 1);
    where.cell[a] = c;
    where.local[a] = std::min(s - c, std::nextafter(1.0, 0.0));
  }
  return where;
}

}  // namespace mpfd::grid
