#include "cosim/recorder.hpp"

#include <fcntl.h>
#include <sys/uio.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <climits>
#include <cstring>

#include "common/core/error.hpp"
#include "cosim/schema.hpp"

namespace mpfd::cosim {
namespace {

/// The writer wakes at least this often, and early once this much is queued.
constexpr auto kWriterPeriod = std::chrono::milliseconds(5);
constexpr std::size_t kWakeBytes = std::size_t{8} << 20;

std::array<unsigned char, 4> little_endian_u32(std::uint32_t value) {
  return {static_cast<unsigned char>(value), static_cast<unsigned char>(value >> 8),
          static_cast<unsigned char>(value >> 16), static_cast<unsigned char>(value >> 24)};
}

}  // namespace

Recorder::Recorder(const std::filesystem::path& path, std::size_t queue_capacity)
    : path_(path), capacity_(queue_capacity) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw Error("cannot create recording '" + path.string() + "': " + std::strerror(errno));
  const std::string schema = schema_descriptor_set().SerializeAsString();
  const auto version = little_endian_u32(recording_format_version);
  const auto length = little_endian_u32(static_cast<std::uint32_t>(schema.size()));
  write_all(recording_magic.data(), recording_magic.size());
  write_all(version.data(), version.size());
  write_all(length.data(), length.size());
  write_all(schema.data(), schema.size());
  if (!write_error_.empty()) {
    ::close(fd_);
    throw Error(write_error_);
  }
  queue_.reserve(queue_capacity);
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
  Entry entry{direction, std::string(peer),
              static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                             std::chrono::steady_clock::now() - start_)
                                             .count()),
              std::vector<zmq::message_t>(parts.size())};
  std::size_t bytes = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    entry.parts[i].copy(parts[i]);
    bytes += parts[i].size();
  }
  std::unique_lock lock(mutex_);
  if (queue_.size() >= capacity_) {
    has_work_.notify_one();
    has_room_.wait(lock, [this] { return queue_.size() < capacity_ || stopping_; });
  }
  if (stopping_) return;
  queue_.push_back(std::move(entry));
  queued_bytes_ += bytes;
  if (queued_bytes_ >= kWakeBytes) has_work_.notify_one();
}

void Recorder::run() {
  std::vector<Entry> batch;
  batch.reserve(capacity_);
  std::unique_lock lock(mutex_);
  while (true) {
    has_work_.wait_for(lock, kWriterPeriod, [this] {
      return queue_.size() >= capacity_ || queued_bytes_ >= kWakeBytes || stopping_;
    });
    const bool last = stopping_;
    batch.swap(queue_);
    queued_bytes_ = 0;
    has_room_.notify_all();
    lock.unlock();
    write_batch(batch);
    const std::size_t count = batch.size();
    batch.clear();
    lock.lock();
    written_ += count;
    if (last && queue_.empty()) return;
  }
}

void Recorder::write_all(const void* data, std::size_t size) {
  const auto* bytes = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd_, bytes, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (write_error_.empty())
        write_error_ =
            "write to recording '" + path_.string() + "' failed: " + std::strerror(errno);
      return;
    }
    bytes += n;
    size -= static_cast<std::size_t>(n);
  }
}

void Recorder::write_batch(std::vector<Entry>& batch) {
  // Record = u32 header length, RecordHeader, then the raw parts; gathered
  // into writev calls of at most IOV_MAX pieces.
  std::vector<std::string> headers(batch.size());
  std::vector<std::array<unsigned char, 4>> lengths(batch.size());
  std::vector<iovec> pieces;
  v1::RecordHeader header;
  for (std::size_t r = 0; r < batch.size(); ++r) {
    header.Clear();
    header.set_direction(batch[r].direction);
    header.set_peer(batch[r].peer);
    header.set_timestamp_ns(batch[r].timestamp_ns);
    for (const auto& part : batch[r].parts) header.add_part_sizes(part.size());
    header.SerializeToString(&headers[r]);
    lengths[r] = little_endian_u32(static_cast<std::uint32_t>(headers[r].size()));
    pieces.push_back({lengths[r].data(), lengths[r].size()});
    pieces.push_back({headers[r].data(), headers[r].size()});
    for (auto& part : batch[r].parts)
      if (part.size() > 0) pieces.push_back({part.data(), part.size()});
  }
  for (std::size_t first = 0; first < pieces.size() && write_error_.empty();) {
    const std::size_t count = std::min<std::size_t>(pieces.size() - first, IOV_MAX);
    ssize_t n = ::writev(fd_, &pieces[first], static_cast<int>(count));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      std::scoped_lock lock(mutex_);
      write_error_ = "write to recording '" + path_.string() + "' failed: " + std::strerror(errno);
      return;
    }
    // Skip what was written; finish a partly written piece with write_all.
    while (first < pieces.size() && n >= static_cast<ssize_t>(pieces[first].iov_len)) {
      n -= static_cast<ssize_t>(pieces[first].iov_len);
      ++first;
    }
    if (n > 0) {
      write_all(static_cast<char*>(pieces[first].iov_base) + n,
                pieces[first].iov_len - static_cast<std::size_t>(n));
      ++first;
    }
  }
}

void Recorder::close() {
  {
    std::scoped_lock lock(mutex_);
    if (fd_ < 0) return;
    stopping_ = true;
  }
  has_work_.notify_all();
  has_room_.notify_all();
  if (writer_.joinable()) writer_.join();
  const bool closed = ::close(fd_) == 0;
  fd_ = -1;
  if (!closed && write_error_.empty()) write_error_ = "closing '" + path_.string() + "' failed";
  if (!write_error_.empty()) throw Error(write_error_);
}

std::uint64_t Recorder::records_written() const {
  std::scoped_lock lock(mutex_);
  return written_;
}

}  // namespace mpfd::cosim
