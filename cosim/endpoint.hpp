#pragma once
// Endpoint strings of the transport: inproc://name, ipc://path, tcp://host:port.

#include <string>
#include <string_view>

namespace mpfd::cosim {

enum class Transport { inproc, ipc, tcp };

/// A validated endpoint. `text` is the string ZeroMQ binds or connects to.
struct Endpoint {
  Transport transport;
  std::string address;  // after "scheme://"
  std::string text;     // the whole string

  bool operator==(const Endpoint&) const = default;
};

/// Parses "inproc://<name>", "ipc://<path>" or "tcp://<host>:<port>" (port 1-65535,
/// or "*" for an ephemeral port when binding). Throws mpfd::Error naming the string
/// and the expected form.
Endpoint parse_endpoint(std::string_view text);

std::string_view transport_name(Transport transport);

}  // namespace mpfd::cosim
