#pragma once
// Cells that hold no tracer after a step. Tracers spread thin where a
// material expands strongly (detonation products grow by orders of magnitude
// in volume), leaving cells inside the expanded material without tracers. The
// thesis leaves them unclassified; copying their previous material would label
// cells that products have filled as air. Instead each empty cell takes the
// material of the nearest cell that holds tracers (breadth-first over face
// neighbours, in cell order, so the result is deterministic); a mixed source
// gives its larger material. A grid with no tracer at all is left as it was.

#include <cstddef>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/material_map.hpp"
#include "fdm_solver/tracer/tracer_bins.hpp"

namespace mpfd::fdm {

/// Reclassifies the empty cells of `map` (bins.count(c) == 0). `queue` is
/// scratch; reserve it to the cell count to avoid allocation.
void fill_empty_cells(const grid::UniformGrid& grid, const TracerBins& bins, MaterialMap& map,
                      std::vector<std::size_t>& queue);

}  // namespace mpfd::fdm
