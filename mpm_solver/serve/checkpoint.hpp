#pragma once
// Checkpoint and Restore of protocol v1 (proto/README.md §8) for the MPM
// zone: every particle array, the injected bodies, the clock and the
// boundary ledger in one HDF5 file (checkpoint_file.hpp), with its SHA-256
// beside it in `<file>.sha256`, as fdm_solver serve does.

#include "cosim/message.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

/// Writes the zone's state to `request.path` (a folder: checkpoint_NNNNNN.h5
/// in it, NNNNNN the step; empty: Setup.output_dir/checkpoints/; relative:
/// under Setup.output_dir), and `<file>.sha256` (sha256sum's format) beside
/// it; both under temporary names renamed into place, the checkpoint last.
/// Throws a non-fatal cosim::ProtocolError{IO} — no partial file left — when a file
/// cannot be written, or when ApplyRegion values wait for the next Advance
/// (they are not part of a checkpoint).
[[nodiscard]] cosim::v1::CheckpointWritten write_checkpoint(ServedZone& zone,
                                                            const cosim::v1::Checkpoint& request);

/// Reads a checkpoint (path as for write_checkpoint) into the zone's solver,
/// which then continues bit for bit as the run that wrote it. The file's
/// SHA-256 is checked against `<file>.sha256` and its contents against the
/// zone before the state is touched; a non-fatal cosim::ProtocolError{IO} names the
/// file and what mismatched. Wakes a dormant zone.
[[nodiscard]] cosim::v1::Restored restore_checkpoint(ServedZone& zone,
                                                     const cosim::v1::Restore& request);

}  // namespace mpfd::mpm
