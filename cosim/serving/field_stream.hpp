#pragma once
// Whole fields in chunks (proto/README.md §15, v1.2): the sender slices
// region arrays into FieldChunk messages within a byte budget, the receiver
// assembles them back and checks that every row arrives once and in order.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "cosim/message.hpp"

namespace mpfd::cosim {

/// The chunk budget when FieldExportRequest.max_chunk_bytes is 0, and the coupler's default.
inline constexpr std::uint64_t kDefaultMaxChunkBytes = std::uint64_t{64} << 20;

/// A field name "<region>/<quantity>" (README §15 rule 1), both parts non-empty.
struct FieldName {
  std::string_view region;
  std::string_view quantity;
};
/// The two parts of `name`, or nothing if it does not follow rule 1.
[[nodiscard]] std::optional<FieldName> split_field_name(std::string_view name);

/// Splits whole fields into FieldChunk messages (README §15 rule 2). `fields` holds arrays with
/// group = region, name = quantity (as an ExportRegion reply holds them); `names` lists the
/// fields to send, each "<region>/<quantity>", in order. Every chunk carries one array (group =
/// transfer_id, name = field) of at most max(1 row, max_chunk_bytes) bytes; a field of 0 rows
/// still sends one chunk so that its shape arrives; the last chunk has last = true. Throws
/// mpfd::Error naming a field absent from `fields` or a name without '/'.
std::vector<Message> slice_into_chunks(const Message& fields, std::string_view transfer_id,
                                       std::span<const std::string> names,
                                       std::uint64_t max_chunk_bytes);

/// The chunks of slice_into_chunks one at a time, so that a sender that sends
/// each before making the next holds one chunk besides the fields, not a
/// second copy of every field. Checks every name when constructed (throws as
/// slice_into_chunks, and for a field named twice), so that a bad name is
/// found before any chunk is sent. Movable: a solver's export hands it to its
/// serve loop.
class ChunkSlicer {
 public:
  /// Slices `fields`, which must outlive the slicer.
  ChunkSlicer(const Message& fields, std::string_view transfer_id,
              std::span<const std::string> names, std::uint64_t max_chunk_bytes);
  /// Slices `fields`, which the slicer owns: each field's frame is released
  /// once its last chunk is made, so that the sender's copy shrinks as the
  /// chunks go (an export of a whole grid holds it about once, not twice).
  ChunkSlicer(Message&& fields, std::string_view transfer_id, std::span<const std::string> names,
              std::uint64_t max_chunk_bytes);
  /// The next chunk, or nothing after the one with last = true.
  [[nodiscard]] std::optional<Message> next();

 private:
  struct Field {
    int array;  // index into the fields' header.arrays (stable when the slicer moves)
    std::vector<std::uint64_t> shape;
    std::uint64_t row_bytes;
    std::uint64_t rows_per_chunk;
  };
  void plan(std::uint64_t max_chunk_bytes);
  [[nodiscard]] const Message& fields() const { return owned_ ? *owned_ : *borrowed_; }

  const Message* borrowed_ = nullptr;
  std::optional<Message> owned_;
  std::string transfer_id_;
  std::vector<std::string> names_;
  std::vector<Field> plan_;
  std::size_t field_ = 0;     // the field the next chunk slices
  std::uint64_t offset_ = 0;  // its first row
  std::uint32_t chunk_index_ = 0;
};

/// Collects the FieldChunk messages of one transfer into whole fields (README §15 rules 2–3).
class FieldAssembly {
 public:
  explicit FieldAssembly(std::string transfer_id);

  /// Adds one chunk (a Message whose body is a FieldChunk). Throws ProtocolError{MALFORMED}
  /// naming the field and what was expected on a gap or overlap of rows, a change of dtype,
  /// shape or row width, a chunk of another transfer, a chunk out of order or after `last`.
  void add(const Message& chunk);

  [[nodiscard]] const std::string& transfer_id() const { return transfer_id_; }
  /// The chunk with last = true has arrived (every field is then whole).
  [[nodiscard]] bool complete() const { return complete_; }
  /// The number of chunks added so far.
  [[nodiscard]] std::uint32_t chunks() const { return next_chunk_; }

  /// The assembled fields as one Message: arrays with group = region, name = quantity, the
  /// field's full shape, dtype and units, readable with view_array like an ExportRegion reply.
  /// Throws ProtocolError{MALFORMED} unless complete. Leaves the assembly empty.
  [[nodiscard]] Message take();

 private:
  struct Field {
    std::string region;
    std::string quantity;
    v1::DType dtype = v1::DTYPE_UNSPECIFIED;
    std::string units;
    std::vector<std::uint64_t> shape;
    std::uint64_t row_bytes = 0;
    std::uint64_t rows = 0;  // received so far
    std::vector<std::byte> bytes;
  };

  Field& start_field(const v1::FieldChunk& body, const v1::ArrayDescriptor& array);
  void check_whole(const Field& field) const;

  std::string transfer_id_;
  std::vector<Field> fields_;
  std::uint32_t next_chunk_ = 0;
  bool complete_ = false;
};

}  // namespace mpfd::cosim
