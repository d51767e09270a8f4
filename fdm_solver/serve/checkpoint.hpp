#pragma once
// Checkpoint and Restore of protocol v1 (proto/README.md §8) for the FDM
// solver: the solver's whole restart state, tracers included, in one HDF5
// file laid out as docs/output.md's `checkpoint_NNNNNN.h5`
// (checkpoint_file.hpp), with its SHA-256 beside it in `<file>.sha256`.

#include "cosim/message.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// Writes the zone's state to `request.path` (a folder: checkpoint_NNNNNN.h5
/// in it, NNNNNN the step; empty: Setup.output_dir/checkpoints/; relative:
/// under Setup.output_dir), and `<file>.sha256` (sha256sum's format) beside
/// it; both are written under temporary names and renamed into place, the
/// checkpoint last. Throws a non-fatal cosim::ProtocolError{IO} — the state is
/// untouched and no partial file is left — when a file cannot be written.
[[nodiscard]] cosim::v1::CheckpointWritten write_checkpoint(const ServedZone& zone,
                                                            const cosim::v1::Checkpoint& request);

/// Reads a checkpoint (path as for write_checkpoint) into the zone's solver,
/// which then continues bit for bit as the run that wrote it. Everything is
/// checked before the state is touched: the file's SHA-256 against
/// `<file>.sha256`, then its contents (checkpoint_file.hpp). A non-fatal
/// cosim::ProtocolError{IO} names the file and what mismatched.
[[nodiscard]] cosim::v1::Restored restore_checkpoint(ServedZone& zone,
                                                     const cosim::v1::Restore& request);

}  // namespace mpfd::fdm
