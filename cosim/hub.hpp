#pragma once
// Coupler side of the transport: one ROUTER socket bound to an endpoint, peers
// known by fixed routing ids ("fdm", "mpm"). Every wait is bounded: silence
// becomes an mpfd::Error naming the peer, the endpoint and the timeout.

#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>
#include <zmq.hpp>

#include "cosim/message.hpp"
#include "cosim/transport_options.hpp"

namespace mpfd::cosim {

class Recorder;

class Hub {
 public:
  Hub(zmq::context_t& context, std::string_view bind_endpoint, TransportOptions options = {});

  /// The endpoint as bound (a tcp port "*" is resolved to the real port).
  const std::string& endpoint() const { return endpoint_; }
  const TransportOptions& options() const { return options_; }

  /// Binds one more endpoint to the same socket (solvers on other addresses
  /// or transports); returns it as bound.
  std::string bind_also(std::string_view bind_endpoint);

  /// Step and time written into the envelope of every message sent from now on.
  void set_clock(std::uint64_t step, double time);
  /// Records every message sent and received (nullptr stops recording).
  void attach_recorder(Recorder* recorder) { recorder_ = recorder; }

  /// Waits for a Hello from each of `peers`, checks the version and answers
  /// HelloAck carrying `run_id`. Returns the Hellos in the order of `peers`.
  std::vector<v1::Hello> accept(std::span<const std::string> peers, std::string_view run_id);

  /// Fills the envelope (version, run id, step, sequence, sender "coupler") and
  /// sends. Returns the sequence number. Throws if the peer is not connected.
  std::uint64_t send(std::string_view peer, Message&& message);
  /// As send(), but only the frames go: `message.header` stays with the caller,
  /// so that a request built every step keeps its memory (no allocation).
  std::uint64_t send_keeping_header(std::string_view peer, Message& message);

  /// The next message from `peer`, waiting at most reply_timeout. A reply with
  /// an Error body is thrown as mpfd::Error naming the peer.
  Message receive_from(std::string_view peer);
  /// As receive_from(peer), waiting at most `timeout` (a whole-field handoff or
  /// import commit may take longer than one step's reply_timeout).
  Message receive_from(std::string_view peer, std::chrono::milliseconds timeout);

  /// One message from each of `peers`, in their order, within one reply_timeout.
  std::vector<Message> gather(std::span<const std::string> peers);

  /// A check run about every `watch_interval` while a wait hears nothing (e.g.
  /// "has a solver process died?"); it throws to end the wait. Empty: none.
  void set_watch(std::function<void()> watch) { watch_ = std::move(watch); }

  /// True once a Shutdown has been sent to `peer` (it may end from then on).
  [[nodiscard]] bool sent_shutdown(std::string_view peer) const {
    return shut_down_peers_.contains(peer);
  }

  /// True once `peer` has answered with a fatal Error: it stops after sending
  /// it, so nothing more is sent to it or awaited from it (proto §9).
  [[nodiscard]] bool reported_fatal_error(std::string_view peer) const {
    return fatal_peers_.contains(peer);
  }

 private:
  void poll_into_pending(std::chrono::milliseconds budget);
  /// poll_into_pending in slices of watch_interval, running the watch after a silent slice.
  void wait_into_pending(std::chrono::milliseconds budget);
  void send_error_to(const std::string& peer, v1::ErrorCode code, const std::string& text);
  [[noreturn]] void throw_timeout(std::string_view peer, std::chrono::milliseconds timeout) const;

  zmq::socket_t socket_;
  TransportOptions options_;
  std::string endpoint_;
  std::vector<std::string> ipc_paths_;  ///< addresses of the ipc endpoints bound
  std::string run_id_;
  std::uint64_t step_ = 0;
  double time_ = 0.0;
  Recorder* recorder_ = nullptr;
  std::map<std::string, std::uint64_t, std::less<>> sequences_;
  std::map<std::string, std::deque<Message>, std::less<>> pending_;
  std::set<std::string, std::less<>> fatal_peers_;
  std::set<std::string, std::less<>> shut_down_peers_;
  std::function<void()> watch_;
  static constexpr std::chrono::milliseconds watch_interval{50};
};

}  // namespace mpfd::cosim
