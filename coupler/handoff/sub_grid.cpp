#include "coupler/handoff/sub_grid.hpp"

#include <algorithm>

#include "common/core/error.hpp"

namespace mpfd::coupler::handoff {
namespace {

constexpr const char* kAxis[3] = {"x", "y", "z"};

std::size_t cell_count(const grid::Index3& cells) {
  return static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
         static_cast<std::size_t>(cells[2]);
}

void require_values(const char* what, const char* name, std::size_t got, std::size_t cells,
                    int row_width) {
  if (row_width < 1)
    throw Error(std::string(what) + ": row width must be >= 1, got " + std::to_string(row_width));
  const std::size_t want = cells * static_cast<std::size_t>(row_width);
  if (got != want)
    throw Error(std::string(what) + ": " + name + " must have " + std::to_string(want) +
                " values (" + std::to_string(cells) + " cells x " + std::to_string(row_width) +
                "), got " + std::to_string(got));
}

void require_in_grid(const grid::UniformGrid& whole, const CellBox& box) {
  for (int a = 0; a < 3; ++a)
    if (box.lo[a] < 0 || box.hi[a] > whole.cells()[a] || box.lo[a] >= box.hi[a])
      throw Error("sub grid: box " + cell_box_text(box) +
                  " must be a non-empty box of the grid's " + std::to_string(whole.cells()[0]) +
                  " x " + std::to_string(whole.cells()[1]) + " x " +
                  std::to_string(whole.cells()[2]) + " cells (axis " + kAxis[a] + ")");
}

// Calls f(grid_index, wire_index) for every cell of a box of `cells`.
template <class F>
void for_each_cell(const grid::Index3& cells, F&& f) {
  const auto nx = static_cast<std::size_t>(cells[0]);
  const auto ny = static_cast<std::size_t>(cells[1]);
  const auto nz = static_cast<std::size_t>(cells[2]);
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) f(i + nx * (j + ny * k), (i * ny + j) * nz + k);
}

template <class T>
void transpose(const char* what, const grid::Index3& cells, std::span<const T> from,
               std::span<T> to, int row_width, bool to_wire) {
  const std::size_t n = cell_count(cells);
  require_values(what, "the input", from.size(), n, row_width);
  require_values(what, "the output", to.size(), n, row_width);
  const auto w = static_cast<std::size_t>(row_width);
  for_each_cell(cells, [&](std::size_t g, std::size_t c) {
    const std::size_t src = to_wire ? g : c;
    const std::size_t dst = to_wire ? c : g;
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(src * w), w,
                to.begin() + static_cast<std::ptrdiff_t>(dst * w));
  });
}

// Calls f(box_index, whole_index) for every cell of the box, both grid order.
template <class F>
void for_each_box_cell(const grid::UniformGrid& whole, const CellBox& box, F&& f) {
  require_in_grid(whole, box);
  std::size_t b = 0;
  for (int k = box.lo[2]; k < box.hi[2]; ++k)
    for (int j = box.lo[1]; j < box.hi[1]; ++j)
      for (int i = box.lo[0]; i < box.hi[0]; ++i) f(b++, whole.cell_index(i, j, k));
}

void copy_box(const grid::UniformGrid& whole, const CellBox& box, std::span<const double> from,
              std::span<double> to, int row_width, bool into_whole) {
  const char* what = into_whole ? "embed_cells" : "extract_cells";
  require_values(what, into_whole ? "the box's values" : "the whole grid's values", from.size(),
                 into_whole ? box.count() : whole.cell_count(), row_width);
  require_values(what, into_whole ? "the whole grid's values" : "the box's values", to.size(),
                 into_whole ? whole.cell_count() : box.count(), row_width);
  const auto w = static_cast<std::size_t>(row_width);
  for_each_box_cell(whole, box, [&](std::size_t b, std::size_t c) {
    const std::size_t src = into_whole ? b : c;
    const std::size_t dst = into_whole ? c : b;
    std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(src * w), w,
                to.begin() + static_cast<std::ptrdiff_t>(dst * w));
  });
}

}  // namespace

std::size_t CellBox::count() const {
  const grid::Index3 n = extent();
  return n[0] > 0 && n[1] > 0 && n[2] > 0 ? cell_count(n) : 0;
}

std::string cell_box_text(const CellBox& box) {
  std::string text;
  for (int a = 0; a < 3; ++a)
    text += (a ? " x [" : "[") + std::to_string(box.lo[a]) + ", " + std::to_string(box.hi[a]) + ")";
  return text;
}

grid::UniformGrid sub_grid(const grid::UniformGrid& whole, const CellBox& box) {
  require_in_grid(whole, box);
  grid::Vec3 origin = whole.origin();
  for (int a = 0; a < 3; ++a) {
    origin[a] += box.lo[a] * whole.spacing()[a];
    if (whole.is_active(a) && box.hi[a] - box.lo[a] < 2)
      throw Error("sub grid: box " + cell_box_text(box) + " must be >= 2 cells wide along " +
                  kAxis[a] + ", an active axis of the grid (one cell would make it inactive)");
  }
  return grid::UniformGrid(origin, whole.spacing(), box.extent());
}

void embed_cells(const grid::UniformGrid& whole, const CellBox& box,
                 std::span<const double> box_values, std::span<double> whole_values,
                 int row_width) {
  copy_box(whole, box, box_values, whole_values, row_width, true);
}

void extract_cells(const grid::UniformGrid& whole, const CellBox& box,
                   std::span<const double> whole_values, std::span<double> box_values,
                   int row_width) {
  copy_box(whole, box, whole_values, box_values, row_width, false);
}

void embed_cells(const grid::UniformGrid& whole, const CellBox& box, const ConservedView& box_cells,
                 ConservedCells& whole_cells) {
  check_sizes(box_cells, box.count());
  check_sizes(whole_cells.view(), whole.cell_count());
  embed_cells(whole, box, box_cells.density, whole_cells.density);
  for (int a = 0; a < 3; ++a)
    embed_cells(whole, box, box_cells.momentum[a], whole_cells.momentum[a]);
  embed_cells(whole, box, box_cells.total_energy, whole_cells.total_energy);
}

void grid_to_wire_order(const grid::Index3& cells, std::span<const double> grid_values,
                        std::span<double> wire_values, int row_width) {
  transpose("grid_to_wire_order", cells, grid_values, wire_values, row_width, true);
}

void grid_to_wire_order(const grid::Index3& cells, std::span<const int> grid_values,
                        std::span<int> wire_values, int row_width) {
  transpose("grid_to_wire_order", cells, grid_values, wire_values, row_width, true);
}

void wire_to_grid_order(const grid::Index3& cells, std::span<const double> wire_values,
                        std::span<double> grid_values, int row_width) {
  transpose("wire_to_grid_order", cells, wire_values, grid_values, row_width, false);
}

void wire_to_grid_order(const grid::Index3& cells, std::span<const int> wire_values,
                        std::span<int> grid_values, int row_width) {
  transpose("wire_to_grid_order", cells, wire_values, grid_values, row_width, false);
}

void grid_to_wire_vectors(const grid::Index3& cells,
                          const std::array<std::span<const double>, 3>& components,
                          std::span<double> wire_vectors) {
  const std::size_t n = cell_count(cells);
  for (int a = 0; a < 3; ++a)
    require_values("grid_to_wire_vectors", "a component", components[a].size(), n, 1);
  require_values("grid_to_wire_vectors", "the wire vectors", wire_vectors.size(), n, 3);
  for_each_cell(cells, [&](std::size_t g, std::size_t w) {
    for (int a = 0; a < 3; ++a) wire_vectors[3 * w + a] = components[a][g];
  });
}

void wire_to_grid_vectors(const grid::Index3& cells, std::span<const double> wire_vectors,
                          const std::array<std::span<double>, 3>& components) {
  const std::size_t n = cell_count(cells);
  for (int a = 0; a < 3; ++a)
    require_values("wire_to_grid_vectors", "a component", components[a].size(), n, 1);
  require_values("wire_to_grid_vectors", "the wire vectors", wire_vectors.size(), n, 3);
  for_each_cell(cells, [&](std::size_t g, std::size_t w) {
    for (int a = 0; a < 3; ++a) components[a][g] = wire_vectors[3 * w + a];
  });
}

}  // namespace mpfd::coupler::handoff
