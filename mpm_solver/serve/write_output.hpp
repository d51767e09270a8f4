#pragma once
// WriteOutput of protocol v1 (proto/README.md §8) for the MPM zone: a
// particle snapshot in the layout of docs/output.md (snapshots/
// snapshot_NNNNNN.h5 and particles.xmf) under Setup.output_dir.

#include "cosim/message.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

/// Writes every particle field of snapshot_particles.hpp at the zone's time.
/// `request.directory` must be empty or Setup.output_dir; `basename` and
/// `fields` are not used (docs/output.md fixes names and the MPM set).
/// Throws cosim::ProtocolError{IO} naming the folder or the writer's failure.
[[nodiscard]] cosim::v1::OutputWritten write_output(ServedZone& zone,
                                                    const cosim::v1::WriteOutput& request);

/// Continues a checkpoint's snapshot series `history` in Setup.output_dir
/// (io::SnapshotWriter::resume), so that a restored zone numbers its snapshots on (from 0
/// again for a checkpoint taken before the first). Nothing without an output_dir. Throws
/// mpfd::Error.
void resume_snapshots(ServedZone& zone, const std::string& history);

}  // namespace mpfd::mpm
