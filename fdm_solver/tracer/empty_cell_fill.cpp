#include "fdm_solver/tracer/empty_cell_fill.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/core/require.hpp"

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

constexpr int kNotOne = -3;  ///< a neighbourhood column holding more than one class

/// Marks kUnassigned in `map` (and counts) every empty cell of row (j, k) whose neighbourhood of
/// reach `reach` (within the grid) did not hold one material in `previous`. The
/// neighbourhood's columns along x ((2 reach + 1)^2 cells each) are read once per row
/// into a window of the last 2 reach + 1.
std::size_t mark_row(const CellOrder& order, std::size_t j, std::size_t k, std::size_t reach,
                     const TracerBins& bins, const MaterialMap& previous, MaterialMap& map) {
  const std::size_t j0 = j > reach ? j - reach : 0, j1 = std::min(j + reach, order.n[1] - 1);
  const std::size_t k0 = k > reach ? k - reach : 0, k1 = std::min(k + reach, order.n[2] - 1);
  const auto column = [&](std::size_t i) {  // its one class, or kNotOne
    const int first = previous.material[i + j0 * order.stride[1] + k0 * order.stride[2]];
    for (std::size_t kk = k0; kk <= k1; ++kk)
      for (std::size_t jj = j0; jj <= j1; ++jj)
        if (previous.material[i + jj * order.stride[1] + kk * order.stride[2]] != first)
          return kNotOne;
    return first;
  };
  const std::size_t nx = order.n[0];
  const std::size_t width = 2 * reach + 1;
  std::array<int, 2 * kMaxFillReach + 1> window{};  // column i + d at [(i + d) % width]
  for (std::size_t i = 0; i < std::min(reach, nx); ++i) window[i % width] = column(i);
  const std::size_t row = j * order.stride[1] + k * order.stride[2];
  std::size_t marked = 0;
  for (std::size_t i = 0; i < nx; ++i) {
    if (i + reach < nx) window[(i + reach) % width] = column(i + reach);
    const int here = window[i % width];
    bool one_material = here >= 0;
    for (std::size_t c = i > reach ? i - reach : 0;
         one_material && c <= std::min(i + reach, nx - 1); ++c)
      one_material = window[c % width] == here;
    if (!one_material && bins.count(row + i) == 0) {
      map.material[row + i] = kUnassigned;
      ++marked;
    }
  }
  return marked;
}

}  // namespace

void fill_empty_cells(const grid::UniformGrid& grid, const TracerBins& bins,
                      const MaterialMap* previous, double cells_moved, MaterialMap& map,
                      FillScratch& scratch) {
  const std::size_t cells = grid.cell_count();
  bool any_tracer = false;
  for (std::size_t c = 0; c < cells && !any_tracer; ++c) any_tracer = bins.count(c) > 0;
  if (!any_tracer) return;

  const CellOrder order(grid);
  // An empty cell holds previous's class (classify_cells); kept where one material was all
  // round, as far as a tracer moved.
  const double reach = std::max(1.0, std::ceil(cells_moved));
  if (previous != nullptr && reach > kMaxFillReach)
    throw Error("empty-cell fill: a tracer moved " + shortest_text(cells_moved) +
                " cells along an axis in one step, beyond the fill's reach of " +
                std::to_string(kMaxFillReach) +
                "; a step within the FDM's stable dt (cfl <= 1) moves tracers at most 2 cells, "
                "so this step was longer than the FDM's stable dt");
  std::size_t unassigned = 0;
  if (previous != nullptr) {
    // Threaded by rows, when the grid (not the row count) is large enough to pay for it.
    const auto rows = static_cast<std::ptrdiff_t>(order.n[1] * order.n[2]);
    const bool threaded = static_cast<std::ptrdiff_t>(cells) >= kMinParallelCount;
#pragma omp parallel for schedule(static) reduction(+ : unassigned) if (threaded)
    for (std::ptrdiff_t row = 0; row < rows; ++row) {
      const auto r = static_cast<std::size_t>(row);
      unassigned += mark_row(order, r % order.n[1], r / order.n[1], static_cast<std::size_t>(reach),
                             bins, *previous, map);
    }
  } else {
    unassigned = parallel_sum(cells, [&](std::size_t c) -> std::size_t {
      if (bins.count(c) > 0) return 0;
      map.material[c] = kUnassigned;
      return 1;
    });
  }
  if (unassigned == 0) return;  // every empty cell kept previous's class and fractions
  const auto for_each_neighbour = [&](std::size_t c, const auto& visit) {
    const auto at = order.at(c);
    for (int a = 0; a < 3; ++a) {
      if (at[a] > 0) visit(c - order.stride[a]);
      if (at[a] + 1 < order.n[a]) visit(c + order.stride[a]);
    }
  };
  scratch.size_for(cells);
  parallel_for(cells, [&](std::size_t c) {
    bool seed = false;
    if (map.material[c] != kUnassigned)
      for_each_neighbour(c, [&](std::size_t n) { seed = seed || map.material[n] == kUnassigned; });
    scratch.seeds[c] = seed ? 1 : 0;
  });
  // Breadth-first from the seeds in cell order, serially: it visits only the cells
  // near where materials met.
  std::vector<std::size_t>& queue = scratch.queue;
  queue.clear();
  for (std::size_t c = 0; c < cells; ++c)
    if (scratch.seeds[c] != 0) queue.push_back(c);
  const std::size_t first_filled = queue.size();
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    const int material = dominant_material(map, c);
    for_each_neighbour(c, [&](std::size_t n) {
      if (map.material[n] != kUnassigned) return;  // known, or already filled
      map.material[n] = material;
      queue.push_back(n);
    });
  }
  // Theta of the filled cells, the queue past its seeds (each unassigned region borders a
  // known cell, as some cell holds tracers, so all are reached). A kept cell holds
  // previous's theta, which for its one material is this already.
  for (std::size_t q = first_filled; q < queue.size(); ++q) {
    const std::size_t c = queue[q];
    for (int r = 0; r < map.material_count; ++r)
      map.theta[static_cast<std::size_t>(r) * cells + c] = r == map.material[c] ? 1.0 : 0.0;
  }
}

}  // namespace mpfd::fdm
