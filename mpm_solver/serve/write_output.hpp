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
/// Throws ProtocolError{IO} naming the folder or the writer's failure.
[[nodiscard]] cosim::v1::OutputWritten write_output(ServedZone& zone,
                                                    const cosim::v1::WriteOutput& request);

}  // namespace mpfd::mpm
