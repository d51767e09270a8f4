#include "mpm_solver/serve/field_export.hpp"

#include <algorithm>
#include <string>

#include "cosim/serving/field_stream.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "mpm_solver/serve/node_transfer.hpp"
#include "mpm_solver/serve/particle_transfer.hpp"

namespace mpfd::mpm {
namespace {

[[noreturn]] void refuse_export(cosim::v1::ErrorCode code, const std::string& what) {
  throw cosim::ProtocolError(code, "FieldExportRequest: " + what, false);
}

/// One region's ExportRegion: the quantities asked of it, in request order.
struct RegionExport {
  const ZoneRegion* region = nullptr;
  cosim::v1::ExportRegion op;
};

std::vector<RegionExport> group_by_region(const ServedZone& zone,
                                          const cosim::v1::FieldExportRequest& request) {
  std::vector<RegionExport> exports;
  std::vector<std::string> seen;
  for (const auto& field : request.fields()) {
    const auto parts = cosim::split_field_name(field);
    if (!parts)
      refuse_export(cosim::v1::ERROR_CODE_MALFORMED,
                    "field '" + field + "': expected '<region>/<quantity>' (proto/README.md §15)");
    if (std::find(seen.begin(), seen.end(), field) != seen.end())
      refuse_export(cosim::v1::ERROR_CODE_MALFORMED, "field '" + field + "' is asked twice");
    seen.push_back(field);
    const std::string name(parts->region);
    const ZoneRegion* region = nullptr;
    try {
      region = &zone.region(name, "FieldExportRequest field '" + field + "'");
    } catch (const cosim::ProtocolError& error) {
      throw cosim::ProtocolError(error.code(), error.what(), false);
    }
    auto found = std::find_if(exports.begin(), exports.end(),
                              [&](const RegionExport& e) { return e.region == region; });
    if (found == exports.end()) {
      exports.push_back({region, {}});
      exports.back().op.set_region(name);
      found = exports.end() - 1;
    }
    found->op.add_quantities(std::string(parts->quantity));
  }
  return exports;
}

}  // namespace

cosim::ChunkSlicer export_fields(ServedZone& zone, const cosim::Message& request) {
  const auto& body = request.header.field_export();
  const std::vector<std::string> names(body.fields().begin(), body.fields().end());
  if (names.empty()) refuse_export(cosim::v1::ERROR_CODE_MALFORMED, "no field asked");
  cosim::Message fields;
  try {
    for (const auto& [region, op] : group_by_region(zone, body)) {
      if (region->kind == cosim::v1::REGION_KIND_NODES)
        export_node_region(zone.solver, *region, op, zone.node_box_map, nullptr, fields);
      else
        export_particle_region(zone.solver, *region, op, fields, zone.particle_scratch);
    }
    return cosim::ChunkSlicer(
        std::move(fields), body.transfer_id(), names,
        body.max_chunk_bytes() == 0 ? cosim::kDefaultMaxChunkBytes : body.max_chunk_bytes());
  } catch (const cosim::ProtocolError& error) {
    // An export changes nothing: every refusal leaves the zone serving.
    throw cosim::ProtocolError(error.code(), error.what(), false);
  } catch (const Error& error) {
    refuse_export(cosim::v1::ERROR_CODE_MALFORMED, error.what());
  }
}

}  // namespace mpfd::mpm
