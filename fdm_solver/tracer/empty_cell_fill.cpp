#include "fdm_solver/tracer/empty_cell_fill.hpp"

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

}  // namespace

void fill_empty_cells(const grid::UniformGrid& grid, const TracerBins& bins, MaterialMap& map,
                      std::vector<std::size_t>& queue) {
  const std::size_t cells = grid.cell_count();
  queue.clear();
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) > 0) queue.push_back(c);
  if (queue.empty() || queue.size() == cells) return;

  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) == 0) map.material[c] = kUnassigned;
  // Breadth-first from every cell with tracers, in cell order. This runs over
  // the whole grid every step, serially: neighbours come from index strides and
  // a cell's position from two divisions. An inactive axis (one cell) has no
  // neighbour either way.
  const auto& n = grid.cells();
  const std::size_t nx = static_cast<std::size_t>(n[0]);
  const std::size_t nxy = nx * static_cast<std::size_t>(n[1]);
  const std::size_t stride[3] = {1, nx, nxy};
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    const int material = dominant_material(map, c);
    const std::size_t k = c / nxy;
    const std::size_t j = (c - k * nxy) / nx;
    const std::size_t at[3] = {c - k * nxy - j * nx, j, k};
    const auto claim = [&](std::size_t neighbour) {
      if (map.material[neighbour] != kUnassigned) return;  // holds tracers, or already filled
      map.material[neighbour] = material;
      queue.push_back(neighbour);
    };
    for (int a = 0; a < 3; ++a) {
      if (at[a] > 0) claim(c - stride[a]);
      if (at[a] + 1 < static_cast<std::size_t>(n[a])) claim(c + stride[a]);
    }
  }
  // Set theta of every filled cell (all are reached: some cell holds tracers).
  for (std::size_t c = 0; c < cells; ++c) {
    if (bins.count(c) > 0) continue;
    for (int r = 0; r < map.material_count; ++r)
      map.theta[static_cast<std::size_t>(r) * cells + c] = r == map.material[c] ? 1.0 : 0.0;
  }
}

}  // namespace mpfd::fdm
