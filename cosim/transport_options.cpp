#include "cosim/transport_options.hpp"

#include <cstdio>
#include <string>

namespace mpfd::cosim {

void apply_options(zmq::socket_t& socket, const TransportOptions& options) {
  const auto ms = [](std::chrono::milliseconds d) { return static_cast<int>(d.count()); };
  socket.set(zmq::sockopt::linger, ms(options.linger));
  socket.set(zmq::sockopt::sndtimeo, ms(options.send_timeout));
  socket.set(zmq::sockopt::heartbeat_ivl, ms(options.heartbeat_interval));
  socket.set(zmq::sockopt::heartbeat_timeout, ms(options.heartbeat_timeout));
  socket.set(zmq::sockopt::heartbeat_ttl, ms(options.heartbeat_timeout));
  socket.set(zmq::sockopt::maxmsgsize, options.max_message_bytes);
  socket.set(zmq::sockopt::sndhwm, 0);
  socket.set(zmq::sockopt::rcvhwm, 0);
  if (options.socket_buffer_bytes > 0) {
    socket.set(zmq::sockopt::sndbuf, options.socket_buffer_bytes);
    socket.set(zmq::sockopt::rcvbuf, options.socket_buffer_bytes);
  }
}

std::string seconds_text(std::chrono::milliseconds duration) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", static_cast<double>(duration.count()) / 1000.0);
  return text;
}

}  // namespace mpfd::cosim
