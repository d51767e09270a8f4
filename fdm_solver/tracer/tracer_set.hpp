#pragma once
// Massless tracer points (T §3.2.2, §3.3) as a structure of arrays: position,
// material index and the volume each carries for the volume fractions
// (T (3-21)-(3-23)). Tracers have no mass; they only mark materials.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::fdm {

/// Material mark of a tracer that left through an outflow face (dropped by compact()).
inline constexpr int kRemovedTracer = -1;
/// Material mark of a tracer whose position became non-finite (dropped by compact()).
inline constexpr int kLostTracer = -2;

struct TracerSet {
  std::array<std::vector<double>, 3> position;  ///< x, y, z [m]
  std::vector<int> material;                    ///< index into the scene's materials
  std::vector<double> volume;                   ///< carried volume V_m [m^3], T (3-21), (3-22)

  [[nodiscard]] std::size_t size() const { return material.size(); }
  void reserve(std::size_t n);
  void add(const grid::Vec3& x, int material_index, double carried_volume);
  /// Drops every tracer marked kRemovedTracer or kLostTracer, keeping the
  /// order of the rest; returns how many were kLostTracer. No allocation.
  std::size_t compact();
};

/// Checked conversion of a per-cell material field stored as doubles (as in
/// initial::CellFields) to indices: each value must be a whole number >= 0.
[[nodiscard]] std::vector<int> material_indices(std::span<const double> cell_material);

/// n tracers per active axis (1 on an inactive axis) in every cell, at the
/// centres of the n^d equal sub-cells, each with its cell's material and
/// volume V_c / n^d (T (3-21) with n_b = n^d). Throws mpfd::Error if the
/// array size is not the cell count, an index is negative or n < 1.
[[nodiscard]] TracerSet seed_from_materials(const grid::UniformGrid& grid,
                                            std::span<const int> cell_material, int n_per_axis);
[[nodiscard]] TracerSet seed_from_materials(const grid::UniformGrid& grid,
                                            std::span<const double> cell_material, int n_per_axis);

}  // namespace mpfd::fdm
