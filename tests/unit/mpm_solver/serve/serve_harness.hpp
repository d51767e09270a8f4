#pragma once
// Drives `mpm_solver serve` from a test: the solver runs serve() on a thread,
// the test is the coupler (a Hub over inproc or ipc). Scenes are given as
// text, as a coupler sends them in Setup.scene_fragment.

#include <chrono>
#include <initializer_list>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/hub.hpp"
#include "mpm_solver/serve/serve.hpp"
#include "tests/unit/cosim/echo_solver.hpp"
#include "tests/unit/cosim/test_endpoints.hpp"

namespace mpfd::mpm::testing {

namespace v1 = cosim::v1;

/// A 2D blast in gas on a 16 x 16 grid of [1 m]^2 (one cell thick in z):
/// a 10x pressure square in the middle of still gas that fills x in [0.25,
/// 0.75), y in [0, 1); outflow on the x faces, walls on y. Particles cross
/// the x = 0.25 and 0.75 planes within a few steps.
inline std::string blast_text() {
  return "name: blast\ntime: {end: 1.0, cfl: 0.4}\n"
         "domain: {lower: [0, 0, 0], upper: [1, 1, 0.0625], cells: [16, 16, 1]}\n"
         "materials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
         "initial: {material: gas, density: 1.0, pressure: 1.0e5}\n"
         "output: {interval: 1.0}\n"
         "solver: {method: mpm}\n"
         "boundaries: {x_lower: outflow, x_upper: outflow, y_lower: wall, y_upper: wall}\n"
         "bodies:\n"
         "  - {name: air, material: gas, density: 1.0, pressure: 1.0e5,\n"
         "     shape: {box: {lower: [0.25, 0, 0], upper: [0.75, 1, 0.0625]}}}\n"
         "  - {name: core, material: gas, density: 2.0, pressure: 1.0e6,\n"
         "     shape: {box: {lower: [0.375, 0.375, 0], upper: [0.625, 0.625, 0.0625]}}}\n";
}

inline v1::Region region(const std::string& name, v1::RegionKind kind,
                         std::initializer_list<long> lo, std::initializer_list<long> hi,
                         std::initializer_list<const char*> quantities = {}) {
  v1::Region r;
  r.set_name(name);
  r.set_kind(kind);
  for (const long l : lo) r.mutable_box()->add_lo(l);
  for (const long h : hi) r.mutable_box()->add_hi(h);
  for (const char* q : quantities) r.add_quantities(q);
  return r;
}

/// The CFDMP regions of proto/README.md §6 on blast_text's grid: ghost nodes
/// around cells x 3..4 (nodes 3..5), interface nodes on the face x = 5, the
/// particles' zone x in cells [4, 12).
inline std::vector<v1::Region> cfdmp_regions() {
  return {region("ghost_nodes", v1::REGION_KIND_NODES, {3, 0, 0}, {6, 17, 1},
                 {"mass", "momentum", "internal_energy"}),
          region("interface_nodes", v1::REGION_KIND_NODES, {5, 0, 0}, {6, 17, 1},
                 {"mass", "momentum", "internal_force"}),
          region("mpm_zone", v1::REGION_KIND_PARTICLES, {4, 0, 0}, {12, 16, 1},
                 {"id", "position", "velocity", "mass", "volume", "internal_energy", "material",
                  "stress"})};
}

/// The CFDMP regions and "all": every particle with every array an import may carry.
inline std::vector<v1::Region> regions_with_all() {
  auto regions = cfdmp_regions();
  regions.push_back(region(
      "all", v1::REGION_KIND_PARTICLES, {0, 0, 0}, {16, 16, 1},
      {"id", "position", "velocity", "mass", "volume", "internal_energy", "material", "stress"}));
  return regions;
}

inline cosim::Message setup(const std::string& scene, const std::vector<v1::Region>& regions,
                            const std::string& output_dir = "", bool dormant = false) {
  cosim::Message message;
  auto& body = *message.header.mutable_setup();
  body.mutable_zone()->set_name("mpm");
  body.mutable_zone()->set_kind(v1::ZONE_KIND_MPM);
  body.mutable_zone()->set_dormant(dormant);
  body.set_scene_fragment(scene);
  for (const auto& r : regions) *body.add_regions() = r;
  body.set_output_dir(output_dir);
  return message;
}

inline v1::Operation& add_op(cosim::Message& message) {
  return *message.header.mutable_exchange()->add_operations();
}

inline void add_advance(cosim::Message& message, double dt, double time) {
  auto& advance = *add_op(message).mutable_advance();
  advance.set_dt(dt);
  advance.set_time(time);
}

inline void add_export(cosim::Message& message, const std::string& region) {
  add_op(message).mutable_export_region()->set_region(region);
}

inline void add_propose(cosim::Message& message) {
  add_op(message).mutable_propose_dt();
}

/// The values of array `name` of group `group` in `message`.
template <typename T = double>
std::vector<T> array_of(const cosim::Message& message, const std::string& group,
                        const std::string& name) {
  const auto view = cosim::view_array<T>(message, group, name);
  return {view.values().begin(), view.values().end()};
}

inline cosim::TransportOptions test_options() {
  cosim::TransportOptions options;
  options.reply_timeout = std::chrono::milliseconds{10000};
  options.idle_timeout = std::chrono::milliseconds{10000};
  return options;
}

/// A coupler (Hub) and `mpm_solver serve` on a thread, connected over `transport`.
class ServedMpm {
 public:
  explicit ServedMpm(cosim::Transport transport = cosim::Transport::inproc)
      : hub_(context_, cosim::testing::unique_bind_endpoint(transport), test_options()),
        solver_([this] {
          serve(context_, {.endpoint = hub_.endpoint(),
                           .name = "mpm",
                           .idle_timeout = test_options().idle_timeout});
        }) {
    const std::vector<std::string> peers{"mpm"};
    hub_.accept(peers, "run-mpm-serve-test");
  }

  /// A solver still serving is shut down, so that it does not wait out its idle timeout.
  ~ServedMpm() {
    if (stopped_) return;
    try {
      shut_down();
    } catch (const Error&) {
      // The test has failed already; the solver stops at its idle timeout.
    }
  }
  ServedMpm(const ServedMpm&) = delete;
  ServedMpm& operator=(const ServedMpm&) = delete;

  cosim::Hub& hub() { return hub_; }

  /// Sends a request and returns the reply; an Error reply is thrown as mpfd::Error.
  cosim::Message request(cosim::Message&& message) {
    hub_.send("mpm", std::move(message));
    return hub_.receive_from("mpm");
  }

  /// Sends a request that must be refused; returns the Error's text.
  std::string refusal(cosim::Message&& message) {
    try {
      request(std::move(message));
    } catch (const Error& error) {
      return error.what();
    }
    return "(no error: the request was answered)";
  }

  /// Waits for serve() to return; what it threw, or "" if it returned.
  std::string stop_reason() {
    stopped_ = true;
    try {
      solver_.join_and_rethrow();
    } catch (const std::exception& error) {
      return error.what();
    }
    return "";
  }

  v1::ShutdownAck shut_down() {
    cosim::Message message;
    message.header.mutable_shutdown()->set_reason("test done");
    const auto ack = request(std::move(message)).header.shutdown_ack();
    stopped_ = true;
    return ack;
  }

 private:
  zmq::context_t context_;
  cosim::Hub hub_;
  cosim::testing::SolverThread solver_;  // last: joined before the hub closes
  bool stopped_ = false;
};

/// Advances the served zone by `steps` steps of its proposed dt; returns the time.
inline double run_steps(ServedMpm& served, double& dt, double time, int steps) {
  for (int s = 0; s < steps; ++s) {
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    add_propose(exchange);
    const auto reply = served.request(std::move(exchange));
    time = reply.header.exchange_result().results(0).advanced().time();
    dt = reply.header.exchange_result().results(1).proposed().stable_dt();
  }
  return time;
}

}  // namespace mpfd::mpm::testing
