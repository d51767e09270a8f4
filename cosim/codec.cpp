#include "cosim/codec.hpp"

#include <limits>
#include <string>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"

namespace mpfd::cosim {
namespace {

std::string who(const v1::Header& header) {
  const auto& sender = header.envelope().sender();
  return sender.empty() ? std::string("an unnamed sender") : "'" + sender + "'";
}

void check_version(const v1::Header& header) {
  if (!header.has_envelope()) throw Error("message header has no envelope");
  const auto major = header.envelope().protocol_major();
  if (major != protocol_major) {
    throw Error("protocol version mismatch: message from " + who(header) + " speaks v" +
                std::to_string(major) + ", this build speaks v" + std::to_string(protocol_major) +
                " (mpfd.cosim.v" + std::to_string(protocol_major) + ")");
  }
}

/// "array 'group/name' from 'sender'", for errors (built only when one is thrown).
std::string where(const v1::Header& header, const v1::ArrayDescriptor& array) {
  return "array '" + array.group() + "/" + array.name() + "' from " + who(header);
}

std::uint64_t expected_bytes(const v1::Header& header, const v1::ArrayDescriptor& array) {
  const std::size_t size = dtype_size(array.dtype());
  if (size == 0) {
    throw Error(where(header, array) + " has unknown dtype " +
                std::to_string(static_cast<int>(array.dtype())));
  }
  std::uint64_t bytes = size;
  for (const auto extent : array.shape()) {
    if (extent != 0 && bytes > std::numeric_limits<std::uint64_t>::max() / extent) {
      throw Error(where(header, array) + " has a shape whose byte size overflows 64 bits");
    }
    bytes *= extent;
  }
  return bytes;
}

}  // namespace

void validate(const Message& message) {
  const auto& header = message.header;
  check_version(header);
  if (header.body_case() == v1::Header::BODY_NOT_SET) {
    throw Error("message from " + who(header) + " has no body (unknown or missing message type)");
  }
  const std::size_t frames = message.frames.size();
  if (static_cast<std::size_t>(header.arrays_size()) != frames) {
    throw Error("message '" + std::string(body_name(header)) + "' from " + who(header) +
                " describes " + std::to_string(header.arrays_size()) + " arrays but carries " +
                std::to_string(frames) + " frames");
  }
  std::vector<bool> seen(frames, false);
  for (const auto& array : header.arrays()) {
    if (array.frame_index() >= frames || seen[array.frame_index()]) {
      throw Error(where(header, array) + " names frame " + std::to_string(array.frame_index()) +
                  ", which is out of range or already described");
    }
    seen[array.frame_index()] = true;
    const auto bytes = expected_bytes(header, array);
    const auto actual = message.frames[array.frame_index()].size();
    if (bytes != actual) {
      throw Error(where(header, array) + " should have " + std::to_string(bytes) +
                  " bytes (shape x " + std::to_string(dtype_size(array.dtype())) +
                  "-byte values) but its frame has " + std::to_string(actual));
    }
  }
}

std::vector<zmq::message_t> encode(Message&& message) {
  std::vector<zmq::message_t> parts;
  parts.reserve(message.frames.size() + 1);
  zmq::message_t header(message.header.ByteSizeLong());
  message.header.SerializeWithCachedSizesToArray(static_cast<std::uint8_t*>(header.data()));
  parts.push_back(std::move(header));
  for (auto& frame : message.frames) parts.push_back(std::move(frame));
  message.frames.clear();
  return parts;
}

Message decode(std::vector<zmq::message_t>&& parts) {
  if (parts.empty()) throw Error("empty multipart message: no header part");
  if (parts.front().size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw Error("message header part of " + std::to_string(parts.front().size()) +
                " bytes exceeds the protobuf limit");
  }
  Message message;
  if (!message.header.ParseFromArray(parts.front().data(),
                                     static_cast<int>(parts.front().size()))) {
    throw Error("message header (" + std::to_string(parts.front().size()) +
                " bytes) is not a valid mpfd.cosim.v1.Header");
  }
  message.frames.reserve(parts.size() - 1);
  for (std::size_t i = 1; i < parts.size(); ++i) message.frames.push_back(std::move(parts[i]));
  validate(message);
  return message;
}

Message decode_bytes(std::span<const std::span<const std::byte>> parts) {
  std::vector<zmq::message_t> copies;
  copies.reserve(parts.size());
  for (const auto part : parts) copies.emplace_back(part.data(), part.size());
  return decode(std::move(copies));
}

}  // namespace mpfd::cosim
