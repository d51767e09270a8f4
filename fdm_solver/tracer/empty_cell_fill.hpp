#pragma once
// Cells that hold no tracer after a step. Tracers spread thin where a
// material expands strongly (detonation products grow by orders of magnitude
// in volume), leaving cells inside the expanded material without tracers. The
// thesis leaves them unclassified. We keep the material of an empty cell whose
// whole neighbourhood of reach R held that one material before the step, R the
// farthest any tracer moved along an axis in the step, rounded up (at least 1;
// the FDM's step bounds it by 2 cfl cells, docs/fdm.md): no other material can
// have reached the cell. Every other empty cell, near where the materials met,
// takes the material of the nearest cell whose material is known (breadth-first
// over face neighbours from the tracer cells and the kept cells, in cell order,
// so the result is deterministic); a mixed source gives its larger material.
// (Filling every empty cell from the nearest tracer cell, as before 2026-12-07,
// labelled whole lines of far air as detonation products where a products tracer
// cell stood out of the cloud's surface.) At an import there is no step before:
// every empty cell is filled. A grid with no tracer at all is left as it was.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/material_map.hpp"
#include "fdm_solver/tracer/tracer_bins.hpp"

namespace mpfd::fdm {

/// Scratch of fill_empty_cells, kept between steps: no allocation once warm.
struct FillScratch {
  std::vector<std::size_t> queue;   ///< breadth-first queue
  std::vector<std::uint8_t> seeds;  ///< per cell: a known cell next to an unassigned one
  /// Sized for `cells` (allocates once).
  void size_for(std::size_t cells) {
    queue.reserve(cells);
    seeds.resize(cells);
  }
};

/// The farthest reach R the fill looks across (cfl <= 1 moves tracers at most 2 cells;
/// a step that moved them farther than this is refused).
inline constexpr int kMaxFillReach = 4;

/// Reclassifies the empty cells of `map` (bins.count(c) == 0), which hold the
/// classification `previous` had before a step in which no tracer moved farther than
/// `cells_moved` cells along an axis (classify_cells). With `previous` null (an
/// import), every empty cell is filled. Throws mpfd::Error if `cells_moved` is beyond
/// kMaxFillReach (and `previous` is given): the step was longer than the FDM's stable dt.
void fill_empty_cells(const grid::UniformGrid& grid, const TracerBins& bins,
                      const MaterialMap* previous, double cells_moved, MaterialMap& map,
                      FillScratch& scratch);

}  // namespace mpfd::fdm
