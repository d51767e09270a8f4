#pragma once
// FieldExportRequest of protocol v1.2 (proto/README.md §15 rule 2) on the MPM
// zone: whole fields "<region>/<quantity>" of its PARTICLES and NODES regions,
// built by the ExportRegion code and sliced into FieldChunk replies.

#include <cstdint>
#include <vector>

#include "cosim/message.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

/// The FieldChunk replies to `request` (a FieldExportRequest), in request
/// order: each region's asked quantities exported as one ExportRegion would
/// (particle_transfer.hpp, node_transfer.hpp), then cut by slice_into_chunks.
/// Everything is built before the first chunk is sent, so a refusal comes
/// instead of it. Throws a non-fatal cosim::ProtocolError (state untouched):
/// MALFORMED for a name that is not "<region>/<quantity>" or is asked twice,
/// UNKNOWN_REGION for a region or quantity the zone did not declare.
[[nodiscard]] std::vector<cosim::Message> export_fields(ServedZone& zone,
                                                        const cosim::Message& request);

}  // namespace mpfd::mpm
