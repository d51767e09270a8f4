#pragma once
// Reads a recording written by Recorder back, message by message, validating
// every length against the file; a corrupt file gives mpfd::Error with the offset.

#include <google/protobuf/descriptor.pb.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "cosim/message.hpp"
#include "mpfd/cosim/v1/recording.pb.h"

namespace mpfd::cosim {

struct RecordedMessage {
  v1::Direction direction;
  std::string peer;
  std::uint64_t timestamp_ns;
  std::uint64_t file_offset;  // where the record starts
  Message message;
};

class Player {
 public:
  explicit Player(const std::filesystem::path& path);

  /// The schema stored in the recording's header.
  const google::protobuf::FileDescriptorSet& schema() const { return schema_; }

  /// The next record, or nothing at the end of the file.
  std::optional<RecordedMessage> next();

 private:
  [[noreturn]] void corrupt(std::uint64_t offset, const std::string& what) const;
  std::uint32_t read_u32(const char* what);
  void read_exact(void* data, std::uint64_t size, const char* what);

  std::filesystem::path path_;
  std::ifstream file_;
  std::uint64_t size_ = 0;
  std::uint64_t offset_ = 0;
  google::protobuf::FileDescriptorSet schema_;
};

}  // namespace mpfd::cosim
