#include "cosim/recorder.hpp"

#include <array>

#include "common/core/error.hpp"
#include "cosim/schema.hpp"

namespace mpfd::cosim {
namespace {

std::array<unsigned char, 4> little_endian_u32(std::uint32_t value) {
  return {static_cast<unsigned char>(value), static_cast<unsigned char>(value >> 8),
          static_cast<unsigned char>(value >> 16), static_cast<unsigned char>(value >> 24)};
}

}  // namespace

Recorder::Recorder(const std::filesystem::path& path, std::size_t queue_capacity)
    : path_(path), file_buffer_(std::size_t{1} << 20), capacity_(queue_capacity) {
  file_ = std::fopen(path.c_str(), "wb");
  if (file_ == nullptr) throw Error("cannot create recording '" + path.string() + "'");
  std::setvbuf(file_, file_buffer_.data(), _IOFBF, file_buffer_.size());
  const std::string schema = schema_descriptor_set().SerializeAsString();
  const auto version = little_endian_u32(recording_format_version);
  const auto length = little_endian_u32(static_cast<std::uint32_t>(schema.size()));
  std::fwrite(recording_magic.data(), 1, recording_magic.size(), file_);
  std::fwrite(version.data(), 1, version.size(), file_);
  std::fwrite(length.data(), 1, length.size(), file_);
  std::fwrite(schema.data(), 1, schema.size(), file_);
  start_ = std::chrono::steady_clock::now();
  writer_ = std::thread([this] { run(); });
}

Recorder::~Recorder() {
  try {
    close();
  } catch (const Error&) {
    // A destructor cannot report; call close() to see write errors.
  }
}

void Recorder::record(v1::Direction direction, std::string_view peer,
                      std::vector<zmq::message_t>& parts) {
  Entry entry;
  entry.header.set_direction(direction);
  entry.header.set_peer(std::string(peer));
  entry.header.set_timestamp_ns(
      static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                     std::chrono::steady_clock::now() - start_)
                                     .count()));
  entry.parts.resize(parts.size());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    entry.header.add_part_sizes(parts[i].size());
    entry.parts[i].copy(parts[i]);
  }
  std::unique_lock lock(mutex_);
  has_room_.wait(lock, [this] { return queue_.size() < capacity_ || stopping_; });
  if (stopping_) return;
  queue_.push_back(std::move(entry));
  has_work_.notify_one();
}

void Recorder::run() {
  std::unique_lock lock(mutex_);
  while (true) {
    has_work_.wait(lock, [this] { return !queue_.empty() || stopping_; });
    if (queue_.empty()) return;
    Entry entry = std::move(queue_.front());
    queue_.pop_front();
    has_room_.notify_one();
    lock.unlock();
    write(entry);
    lock.lock();
    ++written_;
  }
}

void Recorder::write(Entry& entry) {
  const std::string header = entry.header.SerializeAsString();
  const auto length = little_endian_u32(static_cast<std::uint32_t>(header.size()));
  bool ok = std::fwrite(length.data(), 1, length.size(), file_) == length.size();
  ok = ok && std::fwrite(header.data(), 1, header.size(), file_) == header.size();
  for (const auto& part : entry.parts) {
    ok = ok && std::fwrite(part.data(), 1, part.size(), file_) == part.size();
  }
  if (!ok) {
    std::scoped_lock lock(mutex_);
    if (write_error_.empty()) write_error_ = "write to recording '" + path_.string() + "' failed";
  }
}

void Recorder::close() {
  {
    std::scoped_lock lock(mutex_);
    if (file_ == nullptr) return;
    stopping_ = true;
  }
  has_work_.notify_all();
  has_room_.notify_all();
  if (writer_.joinable()) writer_.join();
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!closed && write_error_.empty()) write_error_ = "closing '" + path_.string() + "' failed";
  if (!write_error_.empty()) throw Error(write_error_);
}

std::uint64_t Recorder::records_written() const {
  std::scoped_lock lock(mutex_);
  return written_;
}

}  // namespace mpfd::cosim
