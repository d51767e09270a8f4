// Baseline for hub_roundtrip_bench: the same step (a ROUTER sends one header
// frame + payload to each of two DEALER threads and gathers their echoes)
// with bare ZeroMQ and no protocol, so the report can give MPFD's overhead
// as a ratio measured in one run. ipc and tcp.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>
#include <zmq.hpp>
#include <zmq_addon.hpp>

namespace {

const char* const kPeers[] = {"fdm", "mpm"};

void echo_until_stop(zmq::context_t& context, const std::string& endpoint, const char* id) {
  zmq::socket_t socket(context, zmq::socket_type::dealer);
  socket.set(zmq::sockopt::routing_id, id);
  socket.set(zmq::sockopt::linger, 0);
  socket.connect(endpoint);
  socket.send(zmq::str_buffer("ready"), zmq::send_flags::none);
  while (true) {
    std::vector<zmq::message_t> parts;
    if (!zmq::recv_multipart(socket, std::back_inserter(parts))) return;
    if (parts.size() == 1) return;  // stop
    zmq::message_t reply(parts[1].size());
    std::memcpy(reply.data(), parts[1].data(), parts[1].size());  // a solver fills its export
    socket.send(parts[0], zmq::send_flags::sndmore);
    socket.send(reply, zmq::send_flags::none);
  }
}

// Args: transport (0 ipc, 1 tcp), payload bytes per direction per peer.
void BM_BareZmqStep(benchmark::State& state) {
  zmq::context_t context(1);
  zmq::socket_t hub(context, zmq::socket_type::router);
  hub.set(zmq::sockopt::linger, 0);
  hub.bind(state.range(0) == 0 ? "ipc://" + (std::filesystem::temp_directory_path() /
                                             ("mpfd-bare-" + std::to_string(::getpid())))
                                                .string()
                               : std::string("tcp://127.0.0.1:*"));
  const std::string endpoint = hub.get(zmq::sockopt::last_endpoint);
  std::vector<std::thread> peers;
  for (const char* id : kPeers)
    peers.emplace_back(echo_until_stop, std::ref(context), endpoint, id);
  for (std::size_t i = 0; i < std::size(kPeers); ++i) {
    std::vector<zmq::message_t> ready;
    (void)zmq::recv_multipart(hub, std::back_inserter(ready));
  }
  const std::vector<char> payload(static_cast<std::size_t>(state.range(1)), 1);
  const std::string header(48, 'h');  // the size of a small MPFD header
  for (auto _ : state) {
    for (const char* id : kPeers) {
      hub.send(zmq::buffer(id, std::strlen(id)), zmq::send_flags::sndmore);
      hub.send(zmq::buffer(header), zmq::send_flags::sndmore);
      zmq::message_t body(payload.data(), payload.size());  // a coupler fills its strip
      hub.send(body, zmq::send_flags::none);
    }
    for (std::size_t i = 0; i < std::size(kPeers); ++i) {
      std::vector<zmq::message_t> reply;
      (void)zmq::recv_multipart(hub, std::back_inserter(reply));
      benchmark::DoNotOptimize(reply.data());
    }
  }
  for (const char* id : kPeers) {
    hub.send(zmq::buffer(id, std::strlen(id)), zmq::send_flags::sndmore);
    hub.send(zmq::str_buffer("stop"), zmq::send_flags::none);
  }
  for (auto& peer : peers) peer.join();
}

BENCHMARK(BM_BareZmqStep)
    ->ArgNames({"tcp", "bytes"})
    ->ArgsProduct({{0, 1}, {64, 80'000, 8'000'000}})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

}  // namespace
