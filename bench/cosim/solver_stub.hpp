#pragma once
// A solver stub for the transport benchmark: answers an Exchange by reading the
// applied array and exporting one of the same size from its own buffer (one
// copy, as a real solver exporting its strip), and answers FieldExportRequest
// by streaming its field in chunks.

#include <algorithm>
#include <vector>

#include "cosim/arrays.hpp"
#include "cosim/participant.hpp"

namespace mpfd::cosim::bench {

inline void answer_exchange(Participant& participant, const Message& request,
                            std::vector<double>& strip) {
  Message reply;
  auto& results = *reply.header.mutable_exchange_result();
  for (const auto& operation : request.header.exchange().operations()) {
    auto& result = *results.add_results();
    if (operation.has_apply()) {
      const auto applied = view_array<double>(request, operation.apply().region(), "rho");
      strip.resize(applied.values().size());
      result.set_applied(true);
    } else if (operation.has_export_region()) {
      result.mutable_exported()->set_region(operation.export_region().region());
      add_array(reply, {operation.export_region().region(), "rho", {}, "kg/m^3"},
                std::span<const double>(strip));
    } else if (operation.has_advance()) {
      result.mutable_advanced()->set_time(operation.advance().time() + operation.advance().dt());
    } else if (operation.has_propose_dt()) {
      result.mutable_proposed()->set_stable_dt(1e-7);
    }
  }
  participant.reply(request, std::move(reply));
}

inline void stream_field(Participant& participant, const Message& request,
                         const std::vector<double>& field) {
  const auto& ask = request.header.field_export();
  const std::size_t rows = std::max<std::size_t>(ask.max_chunk_bytes() / sizeof(double), 1);
  std::uint32_t index = 0;
  for (std::size_t offset = 0; offset < field.size(); offset += rows, ++index) {
    const std::size_t count = std::min(rows, field.size() - offset);
    Message chunk;
    auto& body = *chunk.header.mutable_field_chunk();
    body.set_transfer_id(ask.transfer_id());
    body.set_field(ask.fields(0));
    body.add_field_shape(field.size());
    body.set_offset(offset);
    body.set_chunk_index(index);
    body.set_last(offset + count == field.size());
    add_array(chunk, {ask.transfer_id(), ask.fields(0), {}, "kg/m^3"},
              std::span<const double>(field).subspan(offset, count));
    participant.reply(request, std::move(chunk));
  }
}

/// Serves until Shutdown. `field_values` sizes the field streamed on FieldExportRequest.
inline void serve_stub(Participant& participant, std::size_t field_values) {
  std::vector<double> strip;
  const std::vector<double> field(field_values, 1.225);
  while (true) {
    Message request = participant.receive();
    if (request.header.has_shutdown()) {
      Message ack;
      ack.header.mutable_shutdown_ack();
      participant.reply(request, std::move(ack));
      return;
    }
    if (request.header.has_field_export()) {
      stream_field(participant, request, field);
    } else {
      answer_exchange(participant, request, strip);
    }
  }
}

}  // namespace mpfd::cosim::bench
