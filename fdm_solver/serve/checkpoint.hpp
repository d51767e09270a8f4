#pragma once
// Checkpoint and Restore of protocol v1 (proto/README.md §8) for the FDM
// solver: the solver's whole restart state in one HDF5 file, laid out as
// docs/output.md's `checkpoint_NNNNNN.h5`. One-material zones only: the
// tracers of a multi-material zone are not restorable yet.

#include "cosim/message.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// The `format` attribute of a checkpoint and the version read back.
inline constexpr const char* kCheckpointFormat = "mpfd-fdm-checkpoint";
inline constexpr std::int64_t kCheckpointVersion = 1;

/// Writes the zone's state to `request.path` (a folder: checkpoint_NNNNNN.h5
/// in it, NNNNNN the step; empty: Setup.output_dir/checkpoints/; relative:
/// under Setup.output_dir), beside its final name and renamed into place.
/// Throws a non-fatal ProtocolError — the state is untouched and nothing is
/// written — UNEXPECTED for a multi-material zone, IO when the file cannot be
/// written.
[[nodiscard]] cosim::v1::CheckpointWritten write_checkpoint(const ServedZone& zone,
                                                            const cosim::v1::Checkpoint& request);

/// Reads a checkpoint (path as for write_checkpoint) into the zone's solver,
/// which then continues bit for bit as the run that wrote it. Everything is
/// checked before the state is touched; a non-fatal ProtocolError names the
/// file and what mismatched: IO (format, version, grid cells, array sizes,
/// step, start_time), UNEXPECTED (a multi-material zone).
[[nodiscard]] cosim::v1::Restored restore_checkpoint(ServedZone& zone,
                                                     const cosim::v1::Restore& request);

}  // namespace mpfd::fdm
