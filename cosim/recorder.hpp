#pragma once
// Writes every message sent or received to a file, off the step's critical
// path: record() only takes reference-counted copies of the parts (no payload
// copy) and appends them to a queue under a short lock; a background thread
// wakes every few milliseconds (or early when much is queued), takes the whole
// queue and writes it with writev straight from the message buffers. The step
// never waits for the disk unless the queue is full. Format: proto/README.md §10.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>
#include <zmq.hpp>

#include "mpfd/cosim/v1/recording.pb.h"

namespace mpfd::cosim {

class Recorder {
 public:
  /// Creates `path` and writes the file header. When `queue_capacity` records
  /// are waiting, record() blocks until the writer catches up (none is dropped).
  explicit Recorder(const std::filesystem::path& path, std::size_t queue_capacity = 4096);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  /// Queues one message (its parts, header part first). Thread-safe.
  void record(v1::Direction direction, std::string_view peer, std::vector<zmq::message_t>& parts);

  /// Writes everything queued, closes the file; throws mpfd::Error if a write failed.
  void close();

  std::uint64_t records_written() const;

 private:
  struct Entry {
    v1::Direction direction;
    std::string peer;
    std::uint64_t timestamp_ns;
    std::vector<zmq::message_t> parts;
  };
  void run();
  void write_batch(std::vector<Entry>& batch);
  void write_all(const void* data, std::size_t size);

  std::filesystem::path path_;
  int fd_ = -1;
  std::size_t capacity_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::condition_variable has_work_;
  std::condition_variable has_room_;
  std::vector<Entry> queue_;
  std::size_t queued_bytes_ = 0;
  bool stopping_ = false;
  std::string write_error_;
  std::uint64_t written_ = 0;
  std::thread writer_;
};

}  // namespace mpfd::cosim
