#pragma once
// A solver's answer to one request (the serve loops of fdm_solver and
// mpm_solver): one reply, or the FieldChunks of a FieldExportRequest, each cut
// only when the one before is sent (proto/README.md §15 rule 2), so that an
// export of a whole grid does not hold all its chunks besides its fields.

#include <optional>
#include <utility>
#include <variant>

#include "cosim/message.hpp"
#include "cosim/serving/field_stream.hpp"

namespace mpfd::cosim {

class Replies {
 public:
  // Implicit, so that an answer returns its reply or its export as it is.
  Replies(Message reply) : source_(std::optional<Message>(std::move(reply))) {}
  Replies(ChunkSlicer chunks) : source_(std::move(chunks)) {}

  /// The next reply to send, or nothing once every reply has been taken.
  [[nodiscard]] std::optional<Message> next() {
    if (auto* chunks = std::get_if<ChunkSlicer>(&source_)) return chunks->next();
    return std::exchange(std::get<std::optional<Message>>(source_), std::nullopt);
  }

 private:
  std::variant<std::optional<Message>, ChunkSlicer> source_;
};

}  // namespace mpfd::cosim
