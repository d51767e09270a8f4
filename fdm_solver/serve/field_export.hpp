#pragma once
// FieldExportRequest (proto/README.md §15 rule 2, v1.2): whole fields named
// "<region>/<quantity>", taken from the zone as ExportRegion takes them
// (region_transfer.hpp, tracer_region.hpp), sliced into FieldChunk messages.

#include <vector>

#include "cosim/message.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// The FieldChunk messages answering `request`, in order; the serve loop
/// replies each to the request. Throws cosim::ProtocolError, non-fatal and
/// before any chunk exists (a refusal, README §15 rule 2), for a field name
/// without '/', an undeclared region or quantity, or no fields.
[[nodiscard]] std::vector<cosim::Message> export_fields(ServedZone& zone,
                                                        const cosim::Message& request);

}  // namespace mpfd::fdm
