#pragma once
// Tracers binned by cell (counting sort): per-cell, per-material counts
// n_br (T (3-21)-(3-23)) and the cell -> tracers index used for the volume
// fractions and, later, the mixed-cell remap to MPM particles (T (3-19)).

#include <cstddef>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/tracer_set.hpp"

namespace mpfd::fdm {

class TracerBins {
 public:
  /// Bins the tracers (all inside the grid) by the cell holding them; stable:
  /// a cell lists its tracers in increasing index. Reuses its buffers, so
  /// rebinning the same or fewer tracers does not allocate. Throws
  /// mpfd::Error if a tracer's material is not in [0, material_count).
  void rebuild(const grid::UniformGrid& grid, const TracerSet& tracers, int material_count);

  [[nodiscard]] std::size_t cell_count() const { return cell_count_; }
  [[nodiscard]] int material_count() const { return material_count_; }
  /// Tracers of `material` in `cell`, n_br.
  [[nodiscard]] std::size_t count(std::size_t cell, int material) const {
    return counts_[static_cast<std::size_t>(material) * cell_count_ + cell];
  }
  /// All tracers in `cell`, n_b.
  [[nodiscard]] std::size_t count(std::size_t cell) const {
    return offsets_[cell + 1] - offsets_[cell];
  }
  /// Indices into the TracerSet of the tracers in `cell`.
  [[nodiscard]] std::span<const std::size_t> tracers_in(std::size_t cell) const {
    return std::span<const std::size_t>(order_).subspan(offsets_[cell], count(cell));
  }

 private:
  std::size_t cell_count_ = 0;
  int material_count_ = 0;
  std::vector<std::size_t> cell_of_tracer_;
  std::vector<std::size_t> counts_;   // [material * cells + cell]
  std::vector<std::size_t> offsets_;  // cells + 1 prefix sums
  std::vector<std::size_t> cursor_;   // scatter positions
  std::vector<std::size_t> order_;    // tracer indices grouped by cell
};

}  // namespace mpfd::fdm
