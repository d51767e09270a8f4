#pragma once
// A box of cells of a grid as a grid of its own, and the copies between the
// box's arrays and the whole grid's. AFDMP hands over only the fluid zone
// (design §3.5): mpm_to_fdm and fdm_to_mpm run on the fluid box's grid, so
// node_to_cell_share renormalises at the FSI face and no fluid mass reaches
// FSI-zone cells. Two orders of cell values:
//   grid order: x fastest, as grid::UniformGrid stores and the kernels use;
//   wire order: the box's C order, k fastest (proto/README.md §11).
// A row of `row_width` values per cell (vectors [n, 3], per-material arrays
// [n, materials]) moves as one.

#include <array>
#include <cstddef>
#include <span>
#include <string>

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"

namespace mpfd::coupler::handoff {

/// Cells [lo, hi) per axis of a grid (an inactive axis is [0, 1)).
struct CellBox {
  grid::Index3 lo{};
  grid::Index3 hi{};

  [[nodiscard]] grid::Index3 extent() const {
    return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
  }
  [[nodiscard]] std::size_t count() const;
};

/// "[lo0, hi0) x [lo1, hi1) x [lo2, hi2)", for messages.
[[nodiscard]] std::string cell_box_text(const CellBox& box);

/// The grid of the cells of `box`: same spacing, origin at the box's lower
/// corner. Throws mpfd::Error unless the box lies in the grid, is [0, 1) on
/// its inactive axes and at least 2 cells wide on its active ones (a box one
/// cell wide would make the axis inactive and change the shape functions).
[[nodiscard]] grid::UniformGrid sub_grid(const grid::UniformGrid& whole, const CellBox& box);

/// Copies the box's values (grid order of sub_grid(whole, box)) into their
/// cells of the whole grid's array (grid order); other cells are untouched.
/// Throws mpfd::Error on a size mismatch.
void embed_cells(const grid::UniformGrid& whole, const CellBox& box,
                 std::span<const double> box_values, std::span<double> whole_values,
                 int row_width = 1);
/// The inverse of embed_cells: the box's cells of the whole grid's array.
void extract_cells(const grid::UniformGrid& whole, const CellBox& box,
                   std::span<const double> whole_values, std::span<double> box_values,
                   int row_width = 1);
/// embed_cells for the three conserved arrays; `whole_cells` must be sized.
void embed_cells(const grid::UniformGrid& whole, const CellBox& box, const ConservedView& box_cells,
                 ConservedCells& whole_cells);

/// Grid order (x fastest) -> wire order (k fastest) of a box of `cells`.
void grid_to_wire_order(const grid::Index3& cells, std::span<const double> grid_values,
                        std::span<double> wire_values, int row_width = 1);
void grid_to_wire_order(const grid::Index3& cells, std::span<const int> grid_values,
                        std::span<int> wire_values, int row_width = 1);
/// Wire order (k fastest) -> grid order (x fastest).
void wire_to_grid_order(const grid::Index3& cells, std::span<const double> wire_values,
                        std::span<double> grid_values, int row_width = 1);
void wire_to_grid_order(const grid::Index3& cells, std::span<const int> wire_values,
                        std::span<int> grid_values, int row_width = 1);

/// Three component arrays (grid order) -> one wire vector array [n, 3].
void grid_to_wire_vectors(const grid::Index3& cells,
                          const std::array<std::span<const double>, 3>& components,
                          std::span<double> wire_vectors);
/// A wire vector array [n, 3] -> three component arrays (grid order).
void wire_to_grid_vectors(const grid::Index3& cells, std::span<const double> wire_vectors,
                          const std::array<std::span<double>, 3>& components);

}  // namespace mpfd::coupler::handoff
