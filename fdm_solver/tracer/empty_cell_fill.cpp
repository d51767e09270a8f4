#include "fdm_solver/tracer/empty_cell_fill.hpp"

#include <array>

#include "common/core/parallel_for.hpp"

namespace mpfd::fdm {
namespace {

constexpr int kUnassigned = -2;

/// The material a neighbour inherits from cell c.
int dominant_material(const MaterialMap& map, std::size_t c) {
  if (!map.is_mixed(c)) return map.material[c];
  const std::size_t cells = map.material.size();
  int best = 0;
  for (int r = 1; r < map.material_count; ++r)
    if (map.theta[static_cast<std::size_t>(r) * cells + c] >
        map.theta[static_cast<std::size_t>(best) * cells + c])
      best = r;
  return best;
}

/// Index strides and cell positions of a grid in cell order (x fastest).
struct CellOrder {
  explicit CellOrder(const grid::UniformGrid& grid)
      : n{static_cast<std::size_t>(grid.cells()[0]), static_cast<std::size_t>(grid.cells()[1]),
          static_cast<std::size_t>(grid.cells()[2])},
        stride{1, n[0], n[0] * n[1]} {}

  [[nodiscard]] std::array<std::size_t, 3> at(std::size_t c) const {
    const std::size_t k = c / stride[2];
    const std::size_t j = (c - k * stride[2]) / n[0];
    return {c - k * stride[2] - j * n[0], j, k};
  }

  std::array<std::size_t, 3> n;
  std::array<std::size_t, 3> stride;
};

/// Whether cell c and every cell of its 3 x 3 x 3 neighbourhood held the one
/// material `previous.material[c]` (an inactive axis has no neighbour either way).
bool inside_one_material(const CellOrder& order, const MaterialMap& previous, std::size_t c) {
  const int material = previous.material[c];
  if (material == kMixedCell) return false;
  const auto at = order.at(c);
  std::array<std::size_t, 3> lo{}, hi{};
  for (int a = 0; a < 3; ++a) {
    lo[a] = at[a] > 0 ? at[a] - 1 : 0;
    hi[a] = at[a] + 1 < order.n[a] ? at[a] + 1 : at[a];
  }
  for (std::size_t k = lo[2]; k <= hi[2]; ++k)
    for (std::size_t j = lo[1]; j <= hi[1]; ++j)
      for (std::size_t i = lo[0]; i <= hi[0]; ++i)
        if (previous.material[i + j * order.stride[1] + k * order.stride[2]] != material)
          return false;
  return true;
}

}  // namespace

void fill_empty_cells(const grid::UniformGrid& grid, const TracerBins& bins,
                      const MaterialMap& previous, MaterialMap& map,
                      std::vector<std::size_t>& queue) {
  const std::size_t cells = grid.cell_count();
  queue.clear();
  bool any_tracer = false;
  for (std::size_t c = 0; c < cells && !any_tracer; ++c) any_tracer = bins.count(c) > 0;
  if (!any_tracer) return;

  const CellOrder order(grid);
  parallel_for(cells, [&](std::size_t c) {
    if (bins.count(c) == 0 && !inside_one_material(order, previous, c))
      map.material[c] = kUnassigned;  // classify_cells left previous's there
  });
  // Breadth-first from every known cell next to an unassigned one, in cell order.
  // This part runs serially; it visits only the cells near where materials met.
  const auto for_each_neighbour = [&](std::size_t c, const auto& visit) {
    const auto at = order.at(c);
    for (int a = 0; a < 3; ++a) {
      if (at[a] > 0) visit(c - order.stride[a]);
      if (at[a] + 1 < order.n[a]) visit(c + order.stride[a]);
    }
  };
  for (std::size_t c = 0; c < cells; ++c) {
    if (map.material[c] == kUnassigned) continue;
    bool borders = false;
    for_each_neighbour(c,
                       [&](std::size_t n) { borders = borders || map.material[n] == kUnassigned; });
    if (borders) queue.push_back(c);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    const int material = dominant_material(map, c);
    for_each_neighbour(c, [&](std::size_t n) {
      if (map.material[n] != kUnassigned) return;  // known, or already filled
      map.material[n] = material;
      queue.push_back(n);
    });
  }
  // Theta of every filled cell (all are reached: each unassigned region borders a known
  // cell, as some cell holds tracers); a kept cell's is previous's, one material's.
  parallel_for(cells, [&](std::size_t c) {
    if (bins.count(c) > 0 || map.material[c] == previous.material[c]) return;
    for (int r = 0; r < map.material_count; ++r)
      map.theta[static_cast<std::size_t>(r) * cells + c] = r == map.material[c] ? 1.0 : 0.0;
  });
}

}  // namespace mpfd::fdm
