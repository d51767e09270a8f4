#include "fdm_solver/serve/field_export.hpp"

#include <algorithm>
#include <string>

#include "cosim/serving/field_stream.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/region_transfer.hpp"

namespace mpfd::fdm {
namespace {

[[noreturn]] void refuse(cosim::v1::ErrorCode code, const std::string& transfer,
                         const std::string& text) {
  throw cosim::ProtocolError(code, "FieldExportRequest '" + transfer + "': " + text, false);
}

}  // namespace

cosim::ChunkSlicer export_fields(ServedZone& zone, const cosim::Message& request) {
  const auto& body = request.header.field_export();
  const std::string& transfer = body.transfer_id();
  if (body.fields().empty()) refuse(cosim::v1::ERROR_CODE_MALFORMED, transfer, "names no field");
  const std::vector<std::string> names(body.fields().begin(), body.fields().end());
  cosim::Message fields;
  for (auto asked = names.begin(); asked != names.end(); ++asked) {
    const std::string& name = *asked;
    if (std::find(names.begin(), asked, name) != asked)
      refuse(cosim::v1::ERROR_CODE_MALFORMED, transfer, "field '" + name + "' is named twice");
    const auto parts = cosim::split_field_name(name);
    if (!parts)
      refuse(cosim::v1::ERROR_CODE_MALFORMED, transfer,
             "field '" + name + "' is not named \"<region>/<quantity>\"");
    const std::string region(parts->region);
    const std::string quantity(parts->quantity);
    try {
      if (const TracerRegion* tracers = zone.tracer_region(region)) {
        const std::vector<std::string> one{quantity};
        (void)export_tracers(zone.solver, *tracers, one, fields);
        continue;
      }
      if (!zone.regions.contains(region)) zone.unknown_region(region, "FieldExportRequest", false);
      cosim::v1::ExportRegion one;
      one.set_region(region);
      one.add_quantities(quantity);
      (void)export_region(zone.solver, zone.region(region, "FieldExportRequest"), one, fields);
    } catch (const cosim::ProtocolError& error) {
      refuse(error.code(), transfer, error.what());
    }
  }
  const std::uint64_t budget =
      body.max_chunk_bytes() == 0 ? cosim::kDefaultMaxChunkBytes : body.max_chunk_bytes();
  return cosim::ChunkSlicer(std::move(fields), transfer, names, budget);
}

}  // namespace mpfd::fdm
