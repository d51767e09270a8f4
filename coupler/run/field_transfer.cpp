#include "coupler/run/field_transfer.hpp"

#include <chrono>
#include <vector>

#include "common/core/error.hpp"
#include "cosim/serving/field_stream.hpp"
#include "coupler/run/session.hpp"

namespace mpfd::coupler {
namespace {

std::string transfer_text(std::string_view what, std::string_view peer,
                          std::string_view transfer_id, std::span<const std::string> names) {
  std::string fields;
  for (const auto& name : names) fields += (fields.empty() ? "" : ", ") + name;
  return std::string(what) + " of fields [" + fields + "] (transfer '" + std::string(transfer_id) +
         "') with solver '" + std::string(peer) + "'";
}

std::uint64_t frame_bytes(const cosim::Message& message) {
  std::uint64_t bytes = 0;
  for (const auto& frame : message.frames) bytes += frame.size();
  return bytes;
}

}  // namespace

cosim::Message export_fields(cosim::Hub& hub, std::string_view peer, std::string_view transfer_id,
                             std::span<const std::string> names, std::uint64_t max_chunk_bytes,
                             std::chrono::milliseconds timeout, FieldTransferStats* stats) {
  cosim::Message request;
  auto& body = *request.header.mutable_field_export();
  body.set_transfer_id(std::string(transfer_id));
  for (const auto& name : names) body.add_fields(name);
  body.set_max_chunk_bytes(max_chunk_bytes);
  const auto start = std::chrono::steady_clock::now();
  FieldTransferStats sent;
  cosim::FieldAssembly assembly{std::string(transfer_id)};
  try {
    hub.send(peer, std::move(request));
    while (!assembly.complete()) {
      const cosim::Message chunk = hub.receive_from(peer, timeout);
      sent.bytes += frame_bytes(chunk);
      ++sent.chunks;
      assembly.add(chunk);  // names a reply that is not the next chunk
    }
    cosim::Message fields = assembly.take();
    if (stats != nullptr) {
      stats->chunks += sent.chunks;
      stats->bytes += sent.bytes;
      stats->seconds += seconds_since(start);
    }
    return fields;
  } catch (const Error& error) {
    throw Error(transfer_text("export", peer, transfer_id, names) + ": " + error.what());
  }
}

cosim::v1::FieldImportDone import_fields(cosim::Hub& hub, std::string_view peer,
                                         std::string_view transfer_id, cosim::Message fields,
                                         std::span<const std::string> names,
                                         std::uint64_t max_chunk_bytes, bool tracers,
                                         std::chrono::milliseconds timeout,
                                         FieldTransferStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  try {
    // One chunk at a time, each field released once sliced: a whole-grid handoff
    // holds its fields once, not twice, and less as its chunks go.
    FieldTransferStats sent;
    for (cosim::ChunkSlicer slicer(std::move(fields), transfer_id, names, max_chunk_bytes);
         auto next = slicer.next();) {
      cosim::Message& chunk = *next;
      const std::uint32_t index = chunk.header.field_chunk().chunk_index();
      const std::string field = chunk.header.field_chunk().field();
      sent.bytes += frame_bytes(chunk);
      ++sent.chunks;
      hub.send(peer, std::move(chunk));
      const cosim::Message ack = hub.receive_from(peer, timeout);
      if (!ack.header.has_field_chunk_ack() ||
          ack.header.field_chunk_ack().transfer_id() != transfer_id ||
          ack.header.field_chunk_ack().chunk_index() != index)
        throw Error("chunk " + std::to_string(index) + " of field '" + field +
                    "' was answered by '" + std::string(cosim::body_name(ack.header)) +
                    "', expected FieldChunkAck of chunk " + std::to_string(index));
    }
    cosim::Message commit;
    commit.header.mutable_field_import_commit()->set_transfer_id(std::string(transfer_id));
    commit.header.mutable_field_import_commit()->set_tracers(tracers);
    hub.send(peer, std::move(commit));
    const cosim::Message done = hub.receive_from(peer, timeout);
    if (!done.header.has_field_import_done() ||
        done.header.field_import_done().transfer_id() != transfer_id)
      throw Error("the commit was answered by '" + std::string(cosim::body_name(done.header)) +
                  "', expected FieldImportDone");
    if (stats != nullptr) {
      stats->chunks += sent.chunks;
      stats->bytes += sent.bytes;
      stats->seconds += seconds_since(start);
    }
    return done.header.field_import_done();
  } catch (const Error& error) {
    throw Error(transfer_text("import", peer, transfer_id, names) + ": " + error.what());
  }
}

}  // namespace mpfd::coupler
