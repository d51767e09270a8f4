#pragma once
// The coupler's side of the whole-field transfers of protocol v1.2
// (proto/README.md §15): exporting fields from a solver chunk by chunk and
// importing fields into it, each chunk acknowledged before the next is sent
// so that neither side holds more than one chunk in flight. AFDMP's handoffs
// (T (3-3)...(3-8) and (3-14)...(3-20)) move whole zones with these.

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "cosim/hub.hpp"
#include "cosim/message.hpp"

namespace mpfd::coupler {

/// What transfers put on the wire, for summary.json: FieldChunk messages, the
/// bytes of their array frames, and the wall time from request to last reply.
struct FieldTransferStats {
  std::uint32_t chunks = 0;
  std::uint64_t bytes = 0;
  double seconds = 0.0;
};

/// Asks `peer` for the fields `names` ("<region>/<quantity>", README §15
/// rule 1) in chunks of at most `max_chunk_bytes` (0: the solver's default,
/// 64 MiB), waits up to `timeout` for each chunk, and returns the assembled
/// fields: arrays with group = region, name = quantity, as an ExportRegion
/// reply holds them. Adds to `stats` when given. Throws mpfd::Error naming
/// the peer, the transfer and the fields when the solver refuses (its Error
/// text), goes silent, or sends a chunk out of order (FieldAssembly).
[[nodiscard]] cosim::Message export_fields(cosim::Hub& hub, std::string_view peer,
                                           std::string_view transfer_id,
                                           std::span<const std::string> names,
                                           std::uint64_t max_chunk_bytes,
                                           std::chrono::milliseconds timeout,
                                           FieldTransferStats* stats = nullptr);

/// Sends the arrays `names` of `fields` (group = region, name = quantity) to
/// `peer` as FieldChunks of at most `max_chunk_bytes`, each answered by its
/// FieldChunkAck, then FieldImportCommit{transfer_id, tracers}; the envelope's
/// sim_time (Hub::set_clock) becomes the solver's clock (README §15 rule 4).
/// Returns the solver's FieldImportDone (stable dt, totals held after the
/// commit). Adds to `stats` when given. Throws mpfd::Error naming the peer,
/// the transfer and the fields when a field is missing from `fields`, the
/// solver refuses a chunk or the commit, goes silent for `timeout`, or
/// answers with another message. `fields` is consumed: each field is released
/// once its last chunk is sent, all before the commit, when the solver builds
/// its state.
[[nodiscard]] cosim::v1::FieldImportDone import_fields(
    cosim::Hub& hub, std::string_view peer, std::string_view transfer_id, cosim::Message fields,
    std::span<const std::string> names, std::uint64_t max_chunk_bytes, bool tracers,
    std::chrono::milliseconds timeout, FieldTransferStats* stats = nullptr);

}  // namespace mpfd::coupler
