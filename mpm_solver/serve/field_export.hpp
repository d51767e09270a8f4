#pragma once
// FieldExportRequest of protocol v1.2 (proto/README.md §15 rule 2) on the MPM
// zone: whole fields "<region>/<quantity>" of its PARTICLES and NODES regions,
// built by the ExportRegion code and sliced into FieldChunk replies.

#include "cosim/message.hpp"
#include "cosim/serving/field_stream.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

/// The FieldChunk replies to `request` (a FieldExportRequest), in request
/// order: each region's asked quantities exported as one ExportRegion would
/// (particle_transfer.hpp, node_transfer.hpp), then cut one chunk at a time as
/// the serve loop sends them, each field freed once sliced. Everything is
/// built and checked before the first chunk is cut, so a refusal comes
/// instead of it. Throws a non-fatal cosim::ProtocolError (state untouched):
/// MALFORMED for a name that is not "<region>/<quantity>" or is asked twice,
/// UNKNOWN_REGION for a region or quantity the zone did not declare.
[[nodiscard]] cosim::ChunkSlicer export_fields(ServedZone& zone, const cosim::Message& request);

}  // namespace mpfd::mpm
