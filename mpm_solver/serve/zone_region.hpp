#pragma once
// A named region of the MPM zone declared in Setup (proto/README.md §4, §6
// CFDMP regions): a half-open box [lo, hi) of background-grid nodes (NODES:
// ghost_nodes, interface_nodes) or of cells whose particles it holds
// (PARTICLES: mpm_zone), with the quantities a coupler exchanges through it.
// Node values travel in box C order over (i, j, k): k fastest.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "cosim/message.hpp"

namespace mpfd::mpm {

struct ZoneRegion {
  std::string name;
  cosim::v1::RegionKind kind = cosim::v1::REGION_KIND_UNSPECIFIED;
  grid::Index3 lo{};  ///< node indices (NODES) or cell indices (PARTICLES)
  grid::Index3 hi{};
  std::vector<std::string> quantities;

  [[nodiscard]] bool declares(std::string_view quantity) const;
  /// Nodes (NODES) or cells (PARTICLES) in the box.
  [[nodiscard]] std::size_t box_count() const;
  /// Cells whose eight corners are nodes of a NODES box: [lo, hi - 1) on active
  /// axes (the ghost cells whose centres these nodes' shape functions reach).
  [[nodiscard]] std::size_t cell_count(const grid::UniformGrid& grid) const;
};

/// A PARTICLES region's box of cells in metres, [lower, upper) on the grid's
/// active axes (an inactive axis does not constrain).
class RegionExtent {
 public:
  RegionExtent(const ZoneRegion& region, const grid::UniformGrid& grid);
  /// Whether the point (x[0], x[1], x[2]) lies in the box.
  [[nodiscard]] bool contains(const double* x) const {
    for (std::size_t a = 0; a < 3; ++a)
      if (active_[a] && !(x[a] >= lower_[a] && x[a] < upper_[a])) return false;
    return true;
  }
  [[nodiscard]] double lower(std::size_t axis) const { return lower_[axis]; }
  [[nodiscard]] double upper(std::size_t axis) const { return upper_[axis]; }
  [[nodiscard]] bool active(std::size_t axis) const { return active_[axis]; }

 private:
  bool active_[3] = {};
  double lower_[3] = {}, upper_[3] = {};
};

/// The quantities each kind serves: export-only, apply-only and both.
/// NODES: mass, momentum (export, apply), internal_force (apply),
/// internal_energy (export, per cell of cell_count). PARTICLES: id,
/// position, velocity, mass, volume, internal_energy, material, stress,
/// burn_fraction (export); v1.1: outflow_mass, outflow_momentum [1, 3],
/// outflow_energy, one row each: the zone's BoundaryLedger (what particles
/// carried out through outflow and non-reflecting faces since Setup; momentum
/// also minus the impulse of walls, those faces and fixed particle sets).
[[nodiscard]] bool node_quantity_known(std::string_view name);
[[nodiscard]] bool particle_quantity_known(std::string_view name);

/// Checks a Setup region against the zone's grid: kind NODES or PARTICLES,
/// a box of 1 to 3 axes (left-out axes must have one cell), 0 <= lo < hi <=
/// cells (+1 for nodes on an active axis), known quantities (none given:
/// mass, momentum for nodes; id, position, velocity, mass, volume,
/// internal_energy, material for particles). Throws
/// cosim::ProtocolError{UNKNOWN_REGION} naming the region, its box and the rule.
[[nodiscard]] ZoneRegion make_zone_region(const cosim::v1::Region& region,
                                          const grid::UniformGrid& grid);

/// Calls f(n, i, j, k) for each index of the box [lo, hi), n in C order (k fastest).
template <typename F>
void for_each_box_index(const grid::Index3& lo, const grid::Index3& hi, F&& f) {
  std::size_t n = 0;
  for (int i = lo[0]; i < hi[0]; ++i)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int k = lo[2]; k < hi[2]; ++k) f(n++, grid::Index3{i, j, k});
}

}  // namespace mpfd::mpm
