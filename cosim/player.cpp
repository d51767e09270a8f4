#include "cosim/player.hpp"

#include <array>
#include <vector>

#include "common/core/error.hpp"
#include "cosim/codec.hpp"
#include "cosim/schema.hpp"

namespace mpfd::cosim {

Player::Player(const std::filesystem::path& path) : path_(path), file_(path, std::ios::binary) {
  if (!file_) throw Error("cannot open recording '" + path.string() + "'");
  size_ = std::filesystem::file_size(path);
  std::array<char, 8> magic{};
  read_exact(magic.data(), magic.size(), "magic");
  if (magic != recording_magic) corrupt(0, "not an MPFD recording (bad magic)");
  const std::uint32_t version = read_u32("format version");
  if (version != recording_format_version) {
    corrupt(8, "format version " + std::to_string(version) + ", this build reads " +
                   std::to_string(recording_format_version));
  }
  const std::uint32_t schema_size = read_u32("schema length");
  std::string schema(schema_size, '\0');
  read_exact(schema.data(), schema_size, "schema");
  if (!schema_.ParseFromString(schema)) corrupt(16, "schema is not a FileDescriptorSet");
}

std::optional<RecordedMessage> Player::next() {
  if (offset_ == size_) return std::nullopt;
  const std::uint64_t start = offset_;
  const std::uint32_t header_size = read_u32("record header length");
  std::string header_bytes(header_size, '\0');
  read_exact(header_bytes.data(), header_size, "record header");
  v1::RecordHeader header;
  if (!header.ParseFromString(header_bytes)) corrupt(start, "record header does not parse");
  if (header.part_sizes_size() == 0) corrupt(start, "record has no parts");
  std::vector<zmq::message_t> parts;
  parts.reserve(static_cast<std::size_t>(header.part_sizes_size()));
  for (const auto part_size : header.part_sizes()) {
    if (part_size > size_ - offset_) {
      corrupt(offset_, "part of " + std::to_string(part_size) + " bytes runs past the end (" +
                           std::to_string(size_ - offset_) + " bytes left)");
    }
    zmq::message_t part(static_cast<std::size_t>(part_size));
    read_exact(part.data(), part_size, "part");
    parts.push_back(std::move(part));
  }
  RecordedMessage record{header.direction(), header.peer(), header.timestamp_ns(), start, {}};
  try {
    record.message = decode(std::move(parts));
  } catch (const Error& error) {
    corrupt(start, std::string("message does not decode: ") + error.what());
  }
  return record;
}

void Player::corrupt(std::uint64_t offset, const std::string& what) const {
  throw Error("recording '" + path_.string() + "' is corrupt at byte " + std::to_string(offset) +
              ": " + what);
}

std::uint32_t Player::read_u32(const char* what) {
  std::array<unsigned char, 4> bytes{};
  read_exact(bytes.data(), bytes.size(), what);
  return static_cast<std::uint32_t>(bytes[0]) | static_cast<std::uint32_t>(bytes[1]) << 8 |
         static_cast<std::uint32_t>(bytes[2]) << 16 | static_cast<std::uint32_t>(bytes[3]) << 24;
}

void Player::read_exact(void* data, std::uint64_t size, const char* what) {
  if (size > size_ - offset_) {
    corrupt(offset_, std::string(what) + " of " + std::to_string(size) +
                         " bytes runs past the end (" + std::to_string(size_ - offset_) +
                         " bytes left)");
  }
  file_.read(static_cast<char*>(data), static_cast<std::streamsize>(size));
  if (!file_) corrupt(offset_, std::string("read of ") + what + " failed");
  offset_ += size;
}

}  // namespace mpfd::cosim
