#pragma once
// What the whole-field transfer tests share (proto/README.md §15): a 2D
// two-material zone with regions for every field, requests built without a
// transport, and byte access to arrays.

#include <cstring>
#include <string>
#include <vector>

#include "checkpoint_support.hpp"
#include "cosim/serving/field_stream.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/field_export.hpp"
#include "fdm_solver/serve/field_import.hpp"

namespace mpfd::fdm::testing {

inline constexpr int kNx = 10, kNy = 8;

inline v1::Region tracer_box(const std::string& name, std::initializer_list<long> lo,
                             std::initializer_list<long> hi) {
  v1::Region region = cell_box(name, lo, hi);
  region.set_kind(v1::REGION_KIND_TRACERS);
  return region;
}

/// all_cells: every cell quantity over the grid; all_tracers, corner_tracers: TRACERS regions.
inline std::vector<v1::Region> transfer_regions() {
  return {cell_box("all_cells", {0, 0}, {kNx, kNy},
                   {"rho", "momentum", "E", "pressure", "cell_material", "volume_fraction",
                    "material_density", "material_energy"}),
          tracer_box("all_tracers", {0, 0}, {kNx, kNy}),
          tracer_box("corner_tracers", {1, 2}, {4, 5})};
}

/// The corner charge (checkpoint_support.hpp) on kNx x kNy cells; `charge`
/// false keeps both materials but puts only air in the grid (a one-material start).
inline std::unique_ptr<ServedZone> transfer_zone(bool charge = true) {
  std::string scene = corner_charge_text(kNx, kNy);
  if (!charge) scene = scene.substr(0, scene.find("bodies:"));
  return set_up_zone(setup(scene, transfer_regions()).header.setup());
}

inline cosim::Message export_request(const std::string& transfer,
                                     const std::vector<std::string>& fields,
                                     std::uint64_t max_chunk_bytes) {
  cosim::Message message;
  auto& body = *message.header.mutable_field_export();
  body.set_transfer_id(transfer);
  for (const auto& field : fields) body.add_fields(field);
  body.set_max_chunk_bytes(max_chunk_bytes);
  return message;
}

inline cosim::Message commit_request(const std::string& transfer, bool tracers, double sim_time) {
  cosim::Message message;
  message.header.mutable_field_import_commit()->set_transfer_id(transfer);
  message.header.mutable_field_import_commit()->set_tracers(tracers);
  message.header.mutable_envelope()->set_sim_time(sim_time);
  return message;
}

/// The bytes of array group/name.
inline std::vector<std::byte> bytes_of(const cosim::Message& message, const std::string& group,
                                       const std::string& name) {
  const auto& array = cosim::find_descriptor(message, group, name);
  const auto& frame = message.frames.at(array.frame_index());
  std::vector<std::byte> bytes(frame.size());
  if (!bytes.empty()) std::memcpy(bytes.data(), frame.data(), frame.size());
  return bytes;
}

/// Every chunk of `zone`'s answer to the FieldExportRequest `request`, cut at
/// once (the serve loop cuts each as it sends the one before).
inline std::vector<cosim::Message> export_chunks(ServedZone& zone, const cosim::Message& request) {
  auto slicer = export_fields(zone, request);
  std::vector<cosim::Message> chunks;
  while (auto chunk = slicer.next()) chunks.push_back(std::move(*chunk));
  return chunks;
}

/// Exports `fields` from `from` in chunks of `max_chunk_bytes` and feeds every
/// chunk to `to`'s pending import; returns the chunk count.
inline std::size_t stream_fields(ServedZone& from, ServedZone& to, const std::string& transfer,
                                 const std::vector<std::string>& fields,
                                 std::uint64_t max_chunk_bytes) {
  const auto chunks = export_chunks(from, export_request(transfer, fields, max_chunk_bytes));
  for (const auto& chunk : chunks) (void)add_import_chunk(to, chunk);
  return chunks.size();
}

inline const std::vector<std::string> kStateFields{"all_cells/rho", "all_cells/momentum",
                                                   "all_cells/E", "all_tracers/position",
                                                   "all_tracers/material"};

}  // namespace mpfd::fdm::testing
