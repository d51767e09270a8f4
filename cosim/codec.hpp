#pragma once
// Pure encode/decode between a Message and the parts of a multipart ZeroMQ
// message: part 0 is the serialized v1::Header, parts 1..n the raw frames.
// decode never trusts its input: any malformed bytes give mpfd::Error.

#include <cstddef>
#include <span>
#include <vector>

#include "cosim/message.hpp"

namespace mpfd::cosim {

/// Serializes the header into part 0 and moves the frames after it.
std::vector<zmq::message_t> encode(Message&& message);

/// Parses and validates: header parses, envelope present with this build's
/// protocol major version, a body is set, and each frame is described by exactly
/// one array whose byte length is product(shape) * sizeof(dtype).
Message decode(std::vector<zmq::message_t>&& parts);

/// decode() over plain byte buffers (copies them); used by the recorder's player and fuzzers.
Message decode_bytes(std::span<const std::span<const std::byte>> parts);

/// The checks of decode() on an already built message (frames against descriptors).
void validate(const Message& message);

}  // namespace mpfd::cosim
