#include "cosim/hub.hpp"

#include <algorithm>
#include <iterator>
#include <zmq_addon.hpp>

#include "common/core/error.hpp"
#include "cosim/codec.hpp"
#include "cosim/endpoint.hpp"
#include "cosim/ipc_buffers.hpp"
#include "cosim/large_frames.hpp"
#include "cosim/recorder.hpp"

namespace mpfd::cosim {
namespace {

using Clock = std::chrono::steady_clock;

std::chrono::milliseconds remaining(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now());
  return std::max(left, std::chrono::milliseconds{0});
}

}  // namespace

Hub::Hub(zmq::context_t& context, std::string_view bind_endpoint, TransportOptions options)
    : socket_(context, zmq::socket_type::router), options_(options) {
  keep_large_frames_in_heap();
  const Endpoint endpoint = parse_endpoint(bind_endpoint);
  apply_options(socket_, options_);
  socket_.set(zmq::sockopt::router_mandatory, 1);
  try {
    socket_.bind(endpoint.text);
  } catch (const zmq::error_t& error) {
    throw Error("coupler cannot bind '" + endpoint.text + "': " + error.what());
  }
  endpoint_ = socket_.get(zmq::sockopt::last_endpoint);
  if (endpoint.transport == Transport::ipc)  // as bound: "ipc://*" becomes a real path
    ipc_paths_.push_back(parse_endpoint(endpoint_).address);
}

std::string Hub::bind_also(std::string_view bind_endpoint) {
  const Endpoint endpoint = parse_endpoint(bind_endpoint);
  try {
    socket_.bind(endpoint.text);
  } catch (const zmq::error_t& error) {
    throw Error("coupler cannot bind '" + endpoint.text + "': " + error.what());
  }
  const std::string bound = socket_.get(zmq::sockopt::last_endpoint);
  if (endpoint.transport == Transport::ipc) ipc_paths_.push_back(parse_endpoint(bound).address);
  return bound;
}

void Hub::set_clock(std::uint64_t step, double time) {
  step_ = step;
  time_ = time;
}

std::uint64_t Hub::send(std::string_view peer, Message&& message) {
  return send_keeping_header(peer, message);
}

std::uint64_t Hub::send_keeping_header(std::string_view peer, Message& message) {
  auto& envelope = *message.header.mutable_envelope();
  envelope.set_protocol_major(protocol_major);
  envelope.set_protocol_minor(protocol_minor);
  envelope.set_run_id(run_id_);
  envelope.set_step(step_);
  envelope.set_sim_time(time_);
  envelope.set_sender("coupler");
  auto sequence_slot = sequences_.find(peer);
  if (sequence_slot == sequences_.end()) sequence_slot = sequences_.emplace(peer, 0).first;
  const std::uint64_t sequence = ++sequence_slot->second;
  envelope.set_sequence(sequence);
  if (message.header.has_shutdown()) shut_down_peers_.emplace(peer);

  std::vector<zmq::message_t> parts = encode(std::move(message));  // moves the frames only
  if (recorder_ != nullptr) recorder_->record(v1::DIRECTION_SENT, peer, parts);
  try {
    if (!socket_.send(zmq::buffer(peer.data(), peer.size()), zmq::send_flags::sndmore)) {
      throw Error("solver '" + std::string(peer) + "' at " + endpoint_ +
                  " did not accept a message within " + seconds_text(options_.send_timeout));
    }
    if (!zmq::send_multipart(socket_, parts)) {
      throw Error("solver '" + std::string(peer) + "' at " + endpoint_ +
                  " stopped reading mid-message");
    }
  } catch (const zmq::error_t& error) {
    throw Error("cannot send to solver '" + std::string(peer) + "' at " + endpoint_ +
                ": it is not connected (" + error.what() + ")");
  }
  return sequence;
}

void Hub::poll_into_pending(std::chrono::milliseconds budget) {
  zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
  if (zmq::poll(&item, 1, budget) == 0) return;
  std::vector<zmq::message_t> parts;
  if (!zmq::recv_multipart(socket_, std::back_inserter(parts), zmq::recv_flags::dontwait)) return;
  if (parts.size() < 2) return;
  const std::string peer = parts.front().to_string();
  parts.erase(parts.begin());
  if (recorder_ != nullptr) recorder_->record(v1::DIRECTION_RECEIVED, peer, parts);
  Message message;
  try {
    message = decode(std::move(parts));
  } catch (const Error& error) {
    send_error_to(peer, v1::ERROR_CODE_MALFORMED, error.what());
    throw Error("message from solver '" + peer + "' at " + endpoint_ +
                " rejected: " + error.what());
  }
  if (message.header.has_error()) {
    if (message.header.error().fatal()) fatal_peers_.insert(peer);
    throw Error("solver '" + peer + "' reported " +
                v1::ErrorCode_Name(message.header.error().code()) + ": " +
                message.header.error().message());
  }
  pending_[peer].push_back(std::move(message));
}

void Hub::wait_into_pending(std::chrono::milliseconds budget) {
  if (!watch_) {
    poll_into_pending(budget);
    return;
  }
  const auto deadline = Clock::now() + budget;
  while (true) {
    zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
    const auto left = remaining(deadline);
    if (zmq::poll(&item, 1, std::min(left, watch_interval)) > 0) {
      poll_into_pending(std::chrono::milliseconds{0});
      return;
    }
    try {
      watch_();
    } catch (const Error&) {
      // A solver that sent its fatal Error and exited can be seen ended before the
      // message is read: read what it left first, its own error names the cause.
      poll_into_pending(std::chrono::milliseconds{100});
      throw;
    }
    if (remaining(deadline).count() == 0) return;
  }
}

void Hub::send_error_to(const std::string& peer, v1::ErrorCode code, const std::string& text) {
  Message reply;
  reply.header.mutable_error()->set_code(code);
  reply.header.mutable_error()->set_message(text);
  reply.header.mutable_error()->set_fatal(true);
  try {
    send(peer, std::move(reply));
  } catch (const Error&) {
    // Best effort: the peer that sent garbage may already be gone; the caller reports it.
  }
}

void Hub::throw_timeout(std::string_view peer, std::chrono::milliseconds timeout) const {
  throw Error("solver '" + std::string(peer) + "' at " + endpoint_ + " did not answer within " +
              seconds_text(timeout) + " (step " + std::to_string(step_) +
              "); it has died, hung, or never connected");
}

Message Hub::receive_from(std::string_view peer) {
  return receive_from(peer, options_.reply_timeout);
}

Message Hub::receive_from(std::string_view peer, std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  while (true) {
    auto queue = pending_.find(peer);
    if (queue != pending_.end() && !queue->second.empty()) {
      Message message = std::move(queue->second.front());
      queue->second.pop_front();
      return message;
    }
    const auto left = remaining(deadline);
    if (left.count() == 0) throw_timeout(peer, timeout);
    wait_into_pending(left);
  }
}

std::vector<Message> Hub::gather(std::span<const std::string> peers) {
  const auto deadline = Clock::now() + options_.reply_timeout;
  std::vector<Message> replies;
  replies.reserve(peers.size());
  for (const auto& peer : peers) {
    while (pending_[peer].empty()) {
      const auto left = remaining(deadline);
      if (left.count() == 0) throw_timeout(peer, options_.reply_timeout);
      wait_into_pending(left);
    }
    replies.push_back(std::move(pending_[peer].front()));
    pending_[peer].pop_front();
  }
  return replies;
}

std::vector<v1::Hello> Hub::accept(std::span<const std::string> peers, std::string_view run_id) {
  run_id_ = std::string(run_id);
  fatal_peers_.clear();  // a new session: nobody has failed or been shut down yet
  shut_down_peers_.clear();
  std::vector<v1::Hello> hellos;
  for (const auto& peer : peers) {
    Message message = receive_from(peer);
    if (!message.header.has_hello()) {
      throw Error("solver '" + peer + "' sent '" + body_name(message.header) + "' before hello");
    }
    const auto& hello = message.header.hello();
    if (hello.min_major() > protocol_major || hello.max_major() < protocol_major) {
      const std::string text = "solver '" + peer + "' speaks protocol v" +
                               std::to_string(hello.min_major()) + "..v" +
                               std::to_string(hello.max_major()) + ", the coupler speaks v" +
                               std::to_string(protocol_major);
      send_error_to(peer, v1::ERROR_CODE_VERSION_MISMATCH, text);
      throw Error("protocol version mismatch: " + text);
    }
    Message ack;
    auto& body = *ack.header.mutable_hello_ack();
    body.set_major(protocol_major);
    body.set_minor(protocol_minor);
    body.set_run_id(run_id_);
    body.set_heartbeat_interval_s(static_cast<double>(options_.heartbeat_interval.count()) / 1e3);
    body.set_reply_timeout_s(static_cast<double>(options_.reply_timeout.count()) / 1e3);
    send(peer, std::move(ack));
    hellos.push_back(hello);
  }
  // The connections now exist; libzmq sizes only tcp ones (ipc_buffers.hpp).
  for (const auto& path : ipc_paths_) set_ipc_socket_buffers(path, options_.socket_buffer_bytes);
  return hellos;
}

}  // namespace mpfd::cosim
