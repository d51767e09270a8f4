#pragma once
// Socket options shared by the coupler's Hub and the solvers' Participant.

#include <chrono>
#include <cstdint>
#include <zmq.hpp>

namespace mpfd::cosim {

struct TransportOptions {
  /// How long the coupler waits for a solver's reply, and a solver for the coupler's next request.
  std::chrono::milliseconds reply_timeout{5000};
  /// How long a solver waits for the coupler's next request (the coupler may compute in between).
  std::chrono::milliseconds idle_timeout{60000};
  /// A blocked send (peer not reading) fails after this long.
  std::chrono::milliseconds send_timeout{5000};
  /// Unsent messages are dropped this long after close, so closing never hangs.
  std::chrono::milliseconds linger{200};
  /// ZMTP heartbeats: a connection silent for heartbeat_timeout is dropped.
  std::chrono::milliseconds heartbeat_interval{1000};
  std::chrono::milliseconds heartbeat_timeout{5000};
  /// Largest single part accepted; bigger fields travel in FieldChunk messages.
  std::int64_t max_message_bytes = std::int64_t{1} << 30;
  /// Kernel socket buffers for tcp/ipc (0: the OS default).
  int socket_buffer_bytes = 4 << 20;
};

/// Applies linger, timeouts, heartbeats, maximum message size and buffers.
void apply_options(zmq::socket_t& socket, const TransportOptions& options);

/// Seconds as text with one decimal, for error messages ("5.0 s").
std::string seconds_text(std::chrono::milliseconds duration);

}  // namespace mpfd::cosim
