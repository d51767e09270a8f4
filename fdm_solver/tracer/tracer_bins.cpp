#include "fdm_solver/tracer/tracer_bins.hpp"

#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "fdm_solver/tracer/cell_lookup.hpp"

namespace mpfd::fdm {

void TracerBins::rebuild(const grid::UniformGrid& grid, const TracerSet& tracers,
                         int material_count) {
  cell_count_ = grid.cell_count();
  material_count_ = material_count;
  const std::size_t n = tracers.size();
  cell_of_tracer_.resize(n);
  parallel_for(n, [&](std::size_t t) {
    cell_of_tracer_[t] = cell_holding(
        grid, {tracers.position[0][t], tracers.position[1][t], tracers.position[2][t]});
  });

  counts_.assign(static_cast<std::size_t>(material_count) * cell_count_, 0);
  offsets_.assign(cell_count_ + 1, 0);
  for (std::size_t t = 0; t < n; ++t) {
    const int m = tracers.material[t];
    if (m < 0 || m >= material_count)
      throw Error("tracer bins: tracer " + std::to_string(t) + " has material " +
                  std::to_string(m) + ", outside [0, " + std::to_string(material_count) + ")");
    ++counts_[static_cast<std::size_t>(m) * cell_count_ + cell_of_tracer_[t]];
    ++offsets_[cell_of_tracer_[t] + 1];
  }
  for (std::size_t c = 0; c < cell_count_; ++c) offsets_[c + 1] += offsets_[c];

  cursor_.assign(offsets_.begin(), offsets_.end() - 1);
  order_.resize(n);
  for (std::size_t t = 0; t < n; ++t) order_[cursor_[cell_of_tracer_[t]]++] = t;
}

}  // namespace mpfd::fdm
