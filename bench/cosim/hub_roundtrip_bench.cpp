// Per-step round trip through a hub: the coupler sends one Exchange (apply,
// advance, export, propose dt) to each of two solver stubs and gathers both
// replies; plus a chunked whole-field transfer of 64 MiB. ipc and tcp.

#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <memory>
#include <thread>

#include "bench/cosim/solver_stub.hpp"
#include "cosim/hub.hpp"
#include "cosim/recorder.hpp"

namespace mpfd::cosim::bench {
namespace {

constexpr std::size_t field_bytes = std::size_t{64} << 20;
constexpr std::size_t chunk_bytes = std::size_t{4} << 20;
const std::vector<std::string> solver_names{"fdm", "mpm"};

std::string bind_endpoint(int transport) {
  if (transport == 0) {
    return "ipc://" +
           (std::filesystem::temp_directory_path() / ("mpfd-bench-" + std::to_string(::getpid())))
               .string();
  }
  return "tcp://127.0.0.1:*";
}

/// A coupler hub with two stub solvers on their own threads, torn down on destruction.
class Session {
 public:
  explicit Session(int transport) : hub_(context_, bind_endpoint(transport)) {
    for (const auto& name : solver_names) {
      solvers_.emplace_back([this, name] {
        Participant participant(context_, hub_.endpoint(), name);
        participant.connect(v1::Hello{});
        serve_stub(participant, field_bytes / sizeof(double));
      });
    }
    hub_.accept(solver_names, "bench");
  }
  ~Session() {
    for (const auto& name : solver_names) {
      Message shutdown;
      shutdown.header.mutable_shutdown();
      hub_.send(name, std::move(shutdown));
      hub_.receive_from(name);
    }
    for (auto& solver : solvers_) solver.join();
  }
  Hub& hub() { return hub_; }

 private:
  zmq::context_t context_{1};
  Hub hub_;
  std::vector<std::thread> solvers_;
};

Message exchange(const std::vector<double>& ghost_cells, double time) {
  Message message;
  auto* body = message.header.mutable_exchange();
  body->add_operations()->mutable_apply()->set_region("strip");
  body->add_operations()->mutable_advance()->set_dt(1e-7);
  body->mutable_operations(1)->mutable_advance()->set_time(time);
  body->add_operations()->mutable_export_region()->set_region("strip");
  body->add_operations()->mutable_propose_dt();
  add_array(message, {"strip", "rho", {}, "kg/m^3"}, std::span<const double>(ghost_cells));
  return message;
}

// Args: transport (0 ipc, 1 tcp), payload bytes per direction per solver, recording on/off.
void BM_HubStep(benchmark::State& state) {
  Session session(static_cast<int>(state.range(0)));
  const std::vector<double> ghost_cells(static_cast<std::size_t>(state.range(1)) / sizeof(double),
                                        1.225);
  const auto recording = std::filesystem::temp_directory_path() /
                         ("mpfd-bench-" + std::to_string(::getpid()) + ".mpfdrec");
  std::unique_ptr<Recorder> recorder;
  if (state.range(2) != 0) {
    recorder = std::make_unique<Recorder>(recording);
    session.hub().attach_recorder(recorder.get());
  }
  std::uint64_t step = 0;
  for (auto _ : state) {
    ++step;
    session.hub().set_clock(step, static_cast<double>(step) * 1e-7);
    for (const auto& name : solver_names) {
      session.hub().send(name, exchange(ghost_cells, static_cast<double>(step) * 1e-7));
    }
    auto replies = session.hub().gather(solver_names);
    benchmark::DoNotOptimize(replies.data());
  }
  session.hub().attach_recorder(nullptr);
  if (recorder) {
    recorder->close();
    std::filesystem::remove(recording);
  }
  const double one_way = static_cast<double>(solver_names.size() * ghost_cells.size() * 8);
  state.counters["bytes_each_way_per_s"] =
      benchmark::Counter(one_way, benchmark::Counter::kIsIterationInvariantRate);
}

// Args: transport, payload bytes. Recording's cost measured as a paired
// comparison: blocks of steps alternate between recorder detached and
// attached in one session, so machine noise hits both alike. Reports the
// median per-step time of each and the relative change.
void BM_RecordingOverhead(benchmark::State& state) {
  constexpr int kStepsPerBlock = 100;
  Session session(static_cast<int>(state.range(0)));
  const std::vector<double> ghost_cells(static_cast<std::size_t>(state.range(1)) / sizeof(double),
                                        1.225);
  const auto recording = std::filesystem::temp_directory_path() /
                         ("mpfd-bench-pair-" + std::to_string(::getpid()) + ".mpfdrec");
  Recorder recorder(recording);
  std::vector<double> off_us, on_us;
  std::uint64_t step = 0;
  const auto block = [&](bool record) {
    session.hub().attach_recorder(record ? &recorder : nullptr);
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < kStepsPerBlock; ++i) {
      ++step;
      session.hub().set_clock(step, static_cast<double>(step) * 1e-7);
      for (const auto& name : solver_names)
        session.hub().send(name, exchange(ghost_cells, static_cast<double>(step) * 1e-7));
      auto replies = session.hub().gather(solver_names);
      benchmark::DoNotOptimize(replies.data());
    }
    const std::chrono::duration<double, std::micro> spent =
        std::chrono::steady_clock::now() - start;
    (record ? on_us : off_us).push_back(spent.count() / kStepsPerBlock);
  };
  for (auto _ : state) {
    // Alternate which goes first so neither always follows the other.
    const bool record_first = (off_us.size() % 2) == 1;
    block(record_first);
    block(!record_first);
  }
  session.hub().attach_recorder(nullptr);
  recorder.close();
  std::filesystem::remove(recording);
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double off = median(off_us), on = median(on_us);
  state.counters["off_us_per_step"] = off;
  state.counters["on_us_per_step"] = on;
  state.counters["change_percent"] = 100.0 * (on / off - 1.0);
}

// Args: transport. One solver streams a 64 MiB field in 4 MiB chunks to the coupler.
void BM_ChunkedFieldExport(benchmark::State& state) {
  Session session(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Message request;
    auto* body = request.header.mutable_field_export();
    body->set_transfer_id("handoff");
    body->add_fields("rho");
    body->set_max_chunk_bytes(chunk_bytes);
    session.hub().send("fdm", std::move(request));
    while (!session.hub().receive_from("fdm").header.field_chunk().last()) {
    }
  }
  state.counters["bytes_per_s"] = benchmark::Counter(static_cast<double>(field_bytes),
                                                     benchmark::Counter::kIsIterationInvariantRate);
}

void step_arguments(benchmark::internal::Benchmark* bench) {
  bench->ArgNames({"tcp", "bytes", "record"});
  for (const std::int64_t transport : {0, 1}) {
    for (const std::int64_t bytes : {64, 80'000, 8'000'000}) {
      bench->Args({transport, bytes, 0});
      if (bytes <= 80'000) bench->Args({transport, bytes, 1});
    }
  }
}

BENCHMARK(BM_HubStep)->Apply(step_arguments)->UseRealTime()->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RecordingOverhead)
    ->ArgNames({"tcp", "bytes"})
    ->ArgsProduct({{0, 1}, {64, 80'000}})
    ->Iterations(40)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ChunkedFieldExport)
    ->ArgName("tcp")
    ->Arg(0)
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace mpfd::cosim::bench

BENCHMARK_MAIN();
