#pragma once
// A message of protocol v1: the protobuf header (envelope, array descriptors,
// body) and the raw little-endian frames the descriptors describe.

#include <cstdint>
#include <vector>
#include <zmq.hpp>

#include "mpfd/cosim/v1/message.pb.h"

namespace mpfd::cosim {

/// The protocol major version this build speaks (mpfd.cosim.v1).
inline constexpr std::uint32_t protocol_major = 1;
/// The newest minor version of v1 this build understands.
inline constexpr std::uint32_t protocol_minor = 2;

struct Message {
  v1::Header header;
  std::vector<zmq::message_t> frames;  // frame i is described by the array with frame_index i
};

/// Human name of the body case, e.g. "exchange", "hello"; "none" when unset.
const char* body_name(const v1::Header& header);

}  // namespace mpfd::cosim
