#pragma once
// Writes every message sent or received to a file, on a background thread:
// the step only takes reference-counted copies of the parts (no payload copy)
// and pushes them onto a bounded queue. Format: proto/README.md §10.

#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <deque>
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
    v1::RecordHeader header;
    std::vector<zmq::message_t> parts;
  };
  void run();
  void write(Entry& entry);

  std::filesystem::path path_;
  std::FILE* file_ = nullptr;
  std::vector<char> file_buffer_;
  std::size_t capacity_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::condition_variable has_work_;
  std::condition_variable has_room_;
  std::deque<Entry> queue_;
  bool stopping_ = false;
  std::string write_error_;
  std::uint64_t written_ = 0;
  std::thread writer_;
};

}  // namespace mpfd::cosim
