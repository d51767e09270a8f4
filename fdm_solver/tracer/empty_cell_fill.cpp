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
  std::size_t empty = 0;
  for (std::size_t c = 0; c < cells; ++c) empty += bins.count(c) == 0;
  if (empty == 0 || empty == cells) return;

  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) == 0) map.material[c] = kUnassigned;
  queue.clear();
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) > 0) queue.push_back(c);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    const int material = dominant_material(map, c);
    const grid::Index3 cell = grid.cell_of_index(c);
    for (int a = 0; a < 3; ++a) {
      if (!grid.is_active(a)) continue;
      for (const int step : {-1, 1}) {
        grid::Index3 next = cell;
        next[a] += step;
        if (next[a] < 0 || next[a] >= grid.cells()[a]) continue;
        const std::size_t n = grid.cell_index(next);
        if (map.material[n] != kUnassigned) continue;  // holds tracers, or already filled
        map.material[n] = material;
        queue.push_back(n);
      }
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
