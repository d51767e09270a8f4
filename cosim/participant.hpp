#pragma once
// Solver side of the transport: a DEALER socket with a fixed routing id that
// connects to the coupler. Any Euler or MPM code links this to take part.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>
#include <zmq.hpp>

#include "cosim/message.hpp"
#include "cosim/transport_options.hpp"

namespace mpfd::cosim {

class Recorder;

class Participant {
 public:
  /// `name` is the routing id the coupler knows this solver by ("fdm", "mpm").
  Participant(zmq::context_t& context, std::string_view coupler_endpoint, std::string name,
              TransportOptions options = {});

  /// Sends Hello and waits for HelloAck. Throws mpfd::Error if the coupler
  /// rejects the version or does not answer within reply_timeout.
  v1::HelloAck connect(v1::Hello hello);

  /// The coupler's next request, waiting at most idle_timeout since the last
  /// message. Ping is answered here and never returned (it restarts the wait: a
  /// coupler keeps a dormant zone's solver alive with it). A malformed request is
  /// reported to the coupler and thrown.
  Message receive();

  /// Answers `request`: copies its step and time, sets in_reply_to.
  void reply(const Message& request, Message&& reply);

  /// Sends a message that is not a direct reply (a FieldChunk of an export stream).
  void send(Message&& message);

  /// Sends an Error answering `request` (nullptr: not tied to a request).
  void send_error(const Message* request, v1::ErrorCode code, std::string_view text);

  void attach_recorder(Recorder* recorder) { recorder_ = recorder; }
  const std::string& name() const { return name_; }
  const std::string& coupler_endpoint() const { return endpoint_; }
  const v1::HelloAck& session() const { return session_; }

 private:
  void send_with_envelope(Message&& message, std::uint64_t step, double time,
                          std::uint64_t in_reply_to);
  Message receive_within(std::chrono::milliseconds timeout, std::string_view waiting_for);

  zmq::socket_t socket_;
  TransportOptions options_;
  std::string name_;
  std::string endpoint_;
  v1::HelloAck session_;
  std::uint64_t sequence_ = 0;
  Recorder* recorder_ = nullptr;
};

}  // namespace mpfd::cosim
