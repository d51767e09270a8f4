#pragma once
// The multi-material part of a checkpoint (docs/output.md,
// `checkpoint_NNNNNN.h5` groups /tracers and /materials): the whole
// TrackerState, so that a restored zone moves, classifies and closes its
// cells bit for bit as the run that wrote it.

#include "common/grid/uniform_grid.hpp"
#include "common/io/hdf5_file.hpp"
#include "cosim/serving/checkpoint_reader.hpp"
#include "fdm_solver/tracer/multi_material_tracker.hpp"

namespace mpfd::fdm {

/// Writes the tracker's state between steps into groups /tracers and /materials.
void write_tracker_state(io::Hdf5File& h5, const MultiMaterialTracker& tracker,
                         const grid::UniformGrid& grid);

/// Reads them back for a zone of `grid` and `materials` materials; a missing
/// array, a size or an index that does not fit is a reader.mismatch().
[[nodiscard]] TrackerState read_tracker_state(const cosim::CheckpointReader& reader,
                                              const grid::UniformGrid& grid, int materials);

}  // namespace mpfd::fdm
