#pragma once
// The v1 schema as a FileDescriptorSet, written at the head of every recording
// so that a recording can be read without this source tree.

#include <google/protobuf/descriptor.pb.h>

#include <array>
#include <cstdint>

namespace mpfd::cosim {

/// Recording files start with these 8 bytes, then a little-endian u32 format version.
inline constexpr std::array<char, 8> recording_magic{'M', 'P', 'F', 'D', 'R', 'E', 'C', '\0'};
inline constexpr std::uint32_t recording_format_version = 1;

/// Every .proto file of mpfd.cosim.v1 (and google's it imports), dependencies first.
google::protobuf::FileDescriptorSet schema_descriptor_set();

}  // namespace mpfd::cosim
