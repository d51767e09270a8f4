#include "cosim/serving/field_stream.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"

namespace mpfd::cosim {
namespace {

std::uint64_t values_per_row(std::span<const std::uint64_t> shape) {
  return std::accumulate(shape.begin() + 1, shape.end(), std::uint64_t{1}, std::multiplies<>());
}

[[noreturn]] void malformed(const std::string& what) {
  throw ProtocolError(v1::ERROR_CODE_MALFORMED, what, false);
}

}  // namespace

std::optional<FieldName> split_field_name(std::string_view name) {
  const auto slash = name.find('/');
  if (slash == std::string_view::npos || slash == 0 || slash + 1 == name.size()) return {};
  return FieldName{name.substr(0, slash), name.substr(slash + 1)};
}

std::vector<Message> slice_into_chunks(const Message& fields, std::string_view transfer_id,
                                       std::span<const std::string> names,
                                       std::uint64_t max_chunk_bytes) {
  std::vector<Message> chunks;
  ChunkSlicer slicer(fields, transfer_id, names, max_chunk_bytes);
  while (auto chunk = slicer.next()) chunks.push_back(std::move(*chunk));
  return chunks;
}

ChunkSlicer::ChunkSlicer(const Message& fields, std::string_view transfer_id,
                         std::span<const std::string> names, std::uint64_t max_chunk_bytes)
    : borrowed_(&fields), transfer_id_(transfer_id), names_(names.begin(), names.end()) {
  plan(max_chunk_bytes);
}

ChunkSlicer::ChunkSlicer(Message&& fields, std::string_view transfer_id,
                         std::span<const std::string> names, std::uint64_t max_chunk_bytes)
    : owned_(std::move(fields)), transfer_id_(transfer_id), names_(names.begin(), names.end()) {
  plan(max_chunk_bytes);
}

void ChunkSlicer::plan(std::uint64_t max_chunk_bytes) {
  const auto& arrays = fields().header.arrays();
  for (auto full = names_.begin(); full != names_.end(); ++full) {
    if (std::find(names_.begin(), full, *full) != full)
      throw Error("field '" + *full + "' is named twice");
    const auto name = split_field_name(*full);
    if (!name)
      throw Error("field '" + *full + "': expected '<region>/<quantity>' (proto/README.md §15)");
    const auto& array = find_descriptor(fields(), name->region, name->quantity);
    std::vector<std::uint64_t> shape(array.shape().begin(), array.shape().end());
    if (shape.empty()) throw Error("field '" + *full + "' is a scalar; fields have rows");
    const std::uint64_t row_bytes = values_per_row(shape) * dtype_size(array.dtype());
    const std::uint64_t rows_per_chunk =
        row_bytes == 0 ? shape[0] : std::max<std::uint64_t>(max_chunk_bytes / row_bytes, 1);
    int index = 0;  // the array's place in the header (its address does not survive a move)
    while (&arrays[index] != &array) ++index;
    plan_.push_back({index, std::move(shape), row_bytes, rows_per_chunk});
  }
}

std::optional<Message> ChunkSlicer::next() {
  if (field_ >= plan_.size()) return std::nullopt;  // done, or moved from
  const Field& f = plan_[field_];
  const std::string& name = names_[field_];
  const v1::ArrayDescriptor& array = fields().header.arrays(f.array);
  const zmq::message_t& frame = fields().frames.at(array.frame_index());
  const std::uint64_t rows = std::min(f.rows_per_chunk, f.shape[0] - offset_);
  const bool field_done = offset_ + rows == f.shape[0];
  Message chunk;
  auto& body = *chunk.header.mutable_field_chunk();
  body.set_transfer_id(transfer_id_);
  body.set_field(name);
  for (const auto extent : f.shape) body.add_field_shape(extent);
  body.set_offset(offset_);
  body.set_chunk_index(chunk_index_++);
  body.set_last(field_ + 1 == plan_.size() && field_done);
  std::vector<std::uint64_t> chunk_shape = f.shape;
  chunk_shape[0] = rows;
  zmq::message_t data(rows * f.row_bytes);
  if (rows > 0)
    std::memcpy(data.data(), static_cast<const std::byte*>(frame.data()) + offset_ * f.row_bytes,
                rows * f.row_bytes);
  append_frame(chunk, {transfer_id_, name, ArrayShape(chunk_shape), array.units()}, array.dtype(),
               rows * values_per_row(f.shape), std::move(data));
  offset_ += rows;
  if (field_done) {  // a field of 0 rows still sends its one chunk
    if (owned_) owned_->frames.at(array.frame_index()) = zmq::message_t{};
    ++field_;
    offset_ = 0;
  }
  return chunk;
}

FieldAssembly::FieldAssembly(std::string transfer_id) : transfer_id_(std::move(transfer_id)) {}

FieldAssembly::Field& FieldAssembly::start_field(const v1::FieldChunk& body,
                                                 const v1::ArrayDescriptor& array) {
  if (!fields_.empty()) check_whole(fields_.back());
  const auto name = split_field_name(body.field());
  if (!name)
    malformed("FieldChunk field '" + body.field() +
              "': expected '<region>/<quantity>' (proto/README.md §15)");
  for (const auto& field : fields_) {
    if (field.region == name->region && field.quantity == name->quantity)
      malformed("FieldChunk: field '" + body.field() + "' of transfer '" + transfer_id_ +
                "' sent twice");
  }
  if (body.field_shape().empty())
    malformed("FieldChunk field '" + body.field() + "' has an empty field_shape");
  Field field;
  field.region = std::string(name->region);
  field.quantity = std::string(name->quantity);
  field.dtype = array.dtype();
  field.units = array.units();
  field.shape.assign(body.field_shape().begin(), body.field_shape().end());
  field.row_bytes = values_per_row(field.shape) * dtype_size(array.dtype());
  if (field.row_bytes == 0 && values_per_row(field.shape) != 0)
    malformed("FieldChunk field '" + body.field() + "' has no valid dtype");
  field.bytes.resize(field.shape[0] * field.row_bytes);
  fields_.push_back(std::move(field));
  return fields_.back();
}

void FieldAssembly::check_whole(const Field& field) const {
  if (field.rows != field.shape[0])
    malformed("FieldChunk: field '" + field.region + "/" + field.quantity + "' of transfer '" +
              transfer_id_ + "' ended after " + std::to_string(field.rows) + " of " +
              std::to_string(field.shape[0]) + " rows");
}

void FieldAssembly::add(const Message& chunk) {
  if (!chunk.header.has_field_chunk())
    malformed("expected a FieldChunk of transfer '" + transfer_id_ + "', got '" +
              std::string(body_name(chunk.header)) + "'");
  const auto& body = chunk.header.field_chunk();
  if (body.transfer_id() != transfer_id_)
    malformed("FieldChunk of transfer '" + body.transfer_id() + "' while assembling '" +
              transfer_id_ + "'");
  if (complete_)
    malformed("FieldChunk " + std::to_string(body.chunk_index()) + " after the last chunk of '" +
              transfer_id_ + "'");
  if (body.chunk_index() != next_chunk_)
    malformed("FieldChunk of '" + transfer_id_ + "': chunk_index " +
              std::to_string(body.chunk_index()) + ", expected " + std::to_string(next_chunk_));
  if (chunk.header.arrays_size() != 1)
    malformed("FieldChunk " + std::to_string(body.chunk_index()) + " carries " +
              std::to_string(chunk.header.arrays_size()) + " arrays; expected 1");
  const auto& array = chunk.header.arrays(0);
  if (array.group() != transfer_id_ || array.name() != body.field())
    malformed("FieldChunk '" + body.field() + "': its array is '" + array.group() + "/" +
              array.name() + "', expected group '" + transfer_id_ + "' and name '" + body.field() +
              "'");

  const bool same_field =
      !fields_.empty() && body.field() == fields_.back().region + "/" + fields_.back().quantity;
  Field& field = same_field ? fields_.back() : start_field(body, array);
  const std::vector<std::uint64_t> shape(body.field_shape().begin(), body.field_shape().end());
  if (shape != field.shape || array.dtype() != field.dtype)
    malformed("FieldChunk '" + body.field() + "': shape or dtype changed within the field");
  if (body.offset() != field.rows)
    malformed("FieldChunk '" + body.field() + "': offset " + std::to_string(body.offset()) +
              ", expected " + std::to_string(field.rows) + " (rows so far)");
  const std::vector<std::uint64_t> rows_shape(array.shape().begin(), array.shape().end());
  if (rows_shape.size() != shape.size() ||
      !std::equal(rows_shape.begin() + 1, rows_shape.end(), shape.begin() + 1))
    malformed("FieldChunk '" + body.field() + "': its rows do not match field_shape");
  const std::uint64_t rows = rows_shape[0];
  if (field.rows + rows > field.shape[0])
    malformed("FieldChunk '" + body.field() + "': rows " + std::to_string(field.rows) + "+" +
              std::to_string(rows) + " exceed the field's " + std::to_string(field.shape[0]));
  const zmq::message_t& frame = chunk.frames.at(array.frame_index());
  if (frame.size() != rows * field.row_bytes)
    malformed("FieldChunk '" + body.field() + "': frame of " + std::to_string(frame.size()) +
              " bytes, expected " + std::to_string(rows * field.row_bytes));
  if (rows > 0)
    std::memcpy(field.bytes.data() + field.rows * field.row_bytes, frame.data(), frame.size());
  field.rows += rows;
  ++next_chunk_;
  if (body.last()) {
    check_whole(field);
    complete_ = true;
  }
}

Message FieldAssembly::take() {
  if (!complete_)
    malformed("field transfer '" + transfer_id_ + "' is incomplete after " +
              std::to_string(next_chunk_) + " chunks (no chunk with last = true)");
  Message message;
  for (auto& field : fields_) {
    const std::size_t count = field.shape[0] * values_per_row(field.shape);
    zmq::message_t frame;
    if (!field.bytes.empty()) {  // hand the bytes to the frame without a copy
      auto owner = std::make_unique<std::vector<std::byte>>(std::move(field.bytes));
      frame = zmq::message_t(
          owner->data(), owner->size(),
          [](void*, void* hint) { delete static_cast<std::vector<std::byte>*>(hint); },
          owner.get());
      (void)owner.release();  // the frame owns it now
    }
    append_frame(message, {field.region, field.quantity, ArrayShape(field.shape), field.units},
                 field.dtype, count, std::move(frame));
  }
  fields_.clear();
  next_chunk_ = 0;
  complete_ = false;
  return message;
}

}  // namespace mpfd::cosim
