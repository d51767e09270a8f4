#include "cosim/endpoint.hpp"

#include <charconv>

#include "common/core/error.hpp"

namespace mpfd::cosim {
namespace {

[[noreturn]] void reject(std::string_view text, std::string_view rule) {
  throw Error("endpoint '" + std::string(text) + "' is invalid: " + std::string(rule) +
              "; expected inproc://<name>, ipc://<path> or tcp://<host>:<port>");
}

void check_tcp_address(std::string_view text, std::string_view address) {
  const auto colon = address.rfind(':');
  if (colon == std::string_view::npos) reject(text, "tcp needs a port, as in tcp://host:5555");
  const std::string_view host = address.substr(0, colon);
  const std::string_view port = address.substr(colon + 1);
  if (host.empty()) reject(text, "tcp needs a host (use * or 0.0.0.0 to bind every interface)");
  if (port == "*") return;
  unsigned value = 0;
  const auto [end, error] = std::from_chars(port.data(), port.data() + port.size(), value);
  if (port.empty() || error != std::errc{} || end != port.data() + port.size() || value == 0 ||
      value > 65535) {
    reject(text, "tcp port '" + std::string(port) + "' is not a number in 1..65535 or *");
  }
}

}  // namespace

Endpoint parse_endpoint(std::string_view text) {
  const auto separator = text.find("://");
  if (separator == std::string_view::npos) reject(text, "no scheme");
  const std::string_view scheme = text.substr(0, separator);
  const std::string_view address = text.substr(separator + 3);
  Endpoint endpoint{Transport::inproc, std::string(address), std::string(text)};
  if (scheme == "inproc") {
    endpoint.transport = Transport::inproc;
  } else if (scheme == "ipc") {
    endpoint.transport = Transport::ipc;
  } else if (scheme == "tcp") {
    endpoint.transport = Transport::tcp;
    check_tcp_address(text, address);
  } else {
    reject(text, "unknown scheme '" + std::string(scheme) + "'");
  }
  if (address.empty()) reject(text, "empty address after '" + std::string(scheme) + "://'");
  return endpoint;
}

std::string_view transport_name(Transport transport) {
  switch (transport) {
    case Transport::inproc:
      return "inproc";
    case Transport::ipc:
      return "ipc";
    case Transport::tcp:
      return "tcp";
  }
  return "unknown";
}

}  // namespace mpfd::cosim
