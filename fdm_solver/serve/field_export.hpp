#pragma once
// FieldExportRequest (proto/README.md §15 rule 2, v1.2): whole fields named
// "<region>/<quantity>", taken from the zone as ExportRegion takes them
// (region_transfer.hpp, tracer_region.hpp), sliced into FieldChunk messages.

#include "cosim/message.hpp"
#include "cosim/serving/field_stream.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// The FieldChunk messages answering `request`, in order, cut one at a time
/// as the serve loop replies each; the slicer owns the exported fields and
/// frees each once sliced. Throws cosim::ProtocolError, non-fatal and before
/// any chunk exists (a refusal, README §15 rule 2), for a field name without
/// '/' or named twice, an undeclared region or quantity, or no fields.
[[nodiscard]] cosim::ChunkSlicer export_fields(ServedZone& zone, const cosim::Message& request);

}  // namespace mpfd::fdm
