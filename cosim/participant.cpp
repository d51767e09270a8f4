#include "cosim/participant.hpp"

#include <iterator>
#include <zmq_addon.hpp>

#include "common/core/error.hpp"
#include "cosim/codec.hpp"
#include "cosim/endpoint.hpp"
#include "cosim/ipc_buffers.hpp"
#include "cosim/large_frames.hpp"
#include "cosim/recorder.hpp"

namespace mpfd::cosim {

Participant::Participant(zmq::context_t& context, std::string_view coupler_endpoint,
                         std::string name, TransportOptions options)
    : socket_(context, zmq::socket_type::dealer), options_(options), name_(std::move(name)) {
  keep_large_frames_in_heap();
  const Endpoint endpoint = parse_endpoint(coupler_endpoint);
  if (name_.empty()) throw Error("a participant needs a non-empty name (routing id)");
  endpoint_ = endpoint.text;
  apply_options(socket_, options_);
  socket_.set(zmq::sockopt::routing_id, zmq::buffer(name_));
  try {
    socket_.connect(endpoint_);
  } catch (const zmq::error_t& error) {
    throw Error("solver '" + name_ + "' cannot connect to coupler at '" + endpoint_ +
                "': " + error.what());
  }
}

v1::HelloAck Participant::connect(v1::Hello hello) {
  if (hello.min_major() == 0) hello.set_min_major(protocol_major);
  if (hello.max_major() == 0) hello.set_max_major(protocol_major);
  Message message;
  *message.header.mutable_hello() = std::move(hello);
  send_with_envelope(std::move(message), 0, 0.0, 0);
  Message ack = receive_within(options_.reply_timeout, "hello");
  if (!ack.header.has_hello_ack()) {
    throw Error("coupler at " + endpoint_ + " answered hello of solver '" + name_ + "' with '" +
                body_name(ack.header) + "'");
  }
  session_ = ack.header.hello_ack();
  // The connection now exists; libzmq sizes only tcp ones (ipc_buffers.hpp).
  const Endpoint endpoint = parse_endpoint(endpoint_);
  if (endpoint.transport == Transport::ipc)
    set_ipc_socket_buffers(endpoint.address, options_.socket_buffer_bytes);
  return session_;
}

Message Participant::receive() {
  return receive_within(options_.idle_timeout, "a request");
}

Message Participant::receive_within(std::chrono::milliseconds timeout,
                                    std::string_view waiting_for) {
  auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    zmq::pollitem_t item{socket_.handle(), 0, ZMQ_POLLIN, 0};
    if (left.count() <= 0 || zmq::poll(&item, 1, left) == 0) {
      throw Error("solver '" + name_ + "': coupler at " + endpoint_ + " sent no " +
                  std::string(waiting_for) + " within " + seconds_text(timeout) +
                  "; it has died or hung");
    }
    std::vector<zmq::message_t> parts;
    if (!zmq::recv_multipart(socket_, std::back_inserter(parts), zmq::recv_flags::dontwait)) {
      continue;
    }
    if (recorder_ != nullptr) recorder_->record(v1::DIRECTION_RECEIVED, "coupler", parts);
    Message message;
    try {
      message = decode(std::move(parts));
    } catch (const Error& error) {
      send_error(nullptr, v1::ERROR_CODE_MALFORMED, error.what());
      throw Error("solver '" + name_ + "' rejected a message from the coupler at " + endpoint_ +
                  ": " + error.what());
    }
    if (message.header.has_error()) {
      throw Error("coupler at " + endpoint_ + " reported " +
                  v1::ErrorCode_Name(message.header.error().code()) + " to solver '" + name_ +
                  "': " + message.header.error().message());
    }
    if (message.header.has_ping()) {
      Message pong;
      pong.header.mutable_pong();
      reply(message, std::move(pong));
      deadline = std::chrono::steady_clock::now() + timeout;  // the coupler is alive
      continue;
    }
    return message;
  }
}

void Participant::reply(const Message& request, Message&& reply) {
  const auto& envelope = request.header.envelope();
  send_with_envelope(std::move(reply), envelope.step(), envelope.sim_time(), envelope.sequence());
}

void Participant::send(Message&& message) {
  send_with_envelope(std::move(message), 0, 0.0, 0);
}

void Participant::send_error(const Message* request, v1::ErrorCode code, std::string_view text) {
  Message message;
  auto& error = *message.header.mutable_error();
  error.set_code(code);
  error.set_message(std::string(text));
  error.set_fatal(true);
  try {
    if (request != nullptr) {
      reply(*request, std::move(message));
    } else {
      send(std::move(message));
    }
  } catch (const Error&) {
    // Best effort: an error path never waits on the peer (docs/STYLE).
  }
}

void Participant::send_with_envelope(Message&& message, std::uint64_t step, double time,
                                     std::uint64_t in_reply_to) {
  auto& envelope = *message.header.mutable_envelope();
  envelope.set_protocol_major(protocol_major);
  envelope.set_protocol_minor(protocol_minor);
  envelope.set_run_id(session_.run_id());
  envelope.set_sender(name_);
  envelope.set_sequence(++sequence_);
  envelope.set_in_reply_to(in_reply_to);
  if (in_reply_to != 0 || step != 0) {
    envelope.set_step(step);
    envelope.set_sim_time(time);
  }
  std::vector<zmq::message_t> parts = encode(std::move(message));
  if (recorder_ != nullptr) recorder_->record(v1::DIRECTION_SENT, "coupler", parts);
  if (!zmq::send_multipart(socket_, parts)) {
    throw Error("solver '" + name_ + "' could not send to the coupler at " + endpoint_ +
                " within " + seconds_text(options_.send_timeout));
  }
}

}  // namespace mpfd::cosim
