#pragma once
// Drives `fdm_solver serve` from a test: the solver runs serve() on a thread,
// the test is the coupler (a Hub over inproc). Scenes are given as text, as a
// coupler sends them in Setup.scene_fragment.

#include <chrono>
#include <initializer_list>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/hub.hpp"
#include "fdm_solver/serve/serve.hpp"
#include "tests/unit/cosim/echo_solver.hpp"
#include "tests/unit/cosim/test_endpoints.hpp"

namespace mpfd::fdm::testing {

namespace v1 = cosim::v1;

/// Sod's tube (V1) along x with `n` cells: fdm_test_scenes.hpp's sod_tube(0, n) as text.
inline std::string sod_text(int n) {
  return "name: sod\ntime: {end: 1.0}\n"
         "domain: {lower: [0, 0, 0], upper: [1, 1, 1], cells: [" +
         std::to_string(n) +
         ", 1, 1]}\n"
         "materials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
         "initial: {material: gas, density: 0.125, pressure: 0.1}\n"
         "output: {interval: 1.0}\n"
         "bodies:\n  - {name: left, material: gas, density: 1.0, pressure: 1.0,\n"
         "     shape: {box: {lower: [0, 0, 0], upper: [0.5, 1, 1]}}}\n";
}

/// Air at rest (ideal gas, 1.2 kg/m^3, 1e5 Pa) on an 8 x 8 grid of cells, closed by walls.
inline std::string still_air_2d_text() {
  return "name: air\ntime: {end: 1.0}\n"
         "domain: {lower: [0, 0, 0], upper: [1, 1, 0.1], cells: [8, 8, 1]}\n"
         "materials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
         "initial: {material: gas, density: 1.2, pressure: 1.0e5}\n"
         "output: {interval: 1.0}\n"
         "boundaries: {x_lower: wall, x_upper: wall, y_lower: wall, y_upper: wall}\n";
}

inline v1::Region cell_box(const std::string& name, std::initializer_list<long> lo,
                           std::initializer_list<long> hi,
                           std::initializer_list<const char*> quantities = {}) {
  v1::Region region;
  region.set_name(name);
  region.set_kind(v1::REGION_KIND_CELLS);
  for (const long l : lo) region.mutable_box()->add_lo(l);
  for (const long h : hi) region.mutable_box()->add_hi(h);
  for (const char* q : quantities) region.add_quantities(q);
  return region;
}

inline cosim::Message setup(const std::string& scene, const std::vector<v1::Region>& regions,
                            const std::string& output_dir = "") {
  cosim::Message message;
  auto& body = *message.header.mutable_setup();
  body.mutable_zone()->set_name("fdm");
  body.mutable_zone()->set_kind(v1::ZONE_KIND_EULER);
  body.set_scene_fragment(scene);
  for (const auto& region : regions) *body.add_regions() = region;
  body.set_output_dir(output_dir);
  return message;
}

inline void add_advance(cosim::Message& message, double dt, double time) {
  auto& advance = *message.header.mutable_exchange()->add_operations()->mutable_advance();
  advance.set_dt(dt);
  advance.set_time(time);
}

inline void add_export(cosim::Message& message, const std::string& region) {
  message.header.mutable_exchange()->add_operations()->mutable_export_region()->set_region(region);
}

inline void add_apply(cosim::Message& message, const std::string& region,
                      v1::ApplyRegion::Mode mode) {
  auto& apply = *message.header.mutable_exchange()->add_operations()->mutable_apply();
  apply.set_region(region);
  apply.set_mode(mode);
}

/// The values of array `name` of group `group` in `message`.
inline std::vector<double> array_of(const cosim::Message& message, const std::string& group,
                                    const std::string& name) {
  const auto view = cosim::view_array<double>(message, group, name);
  return {view.values().begin(), view.values().end()};
}

/// A coupler (Hub) and `fdm_solver serve` on a thread, connected over inproc.
class ServedFdm {
 public:
  ServedFdm()
      : hub_(context_, cosim::testing::unique_bind_endpoint(cosim::Transport::inproc), options()),
        solver_([this] {
          serve(
              context_,
              {.endpoint = hub_.endpoint(), .name = "fdm", .idle_timeout = options().idle_timeout});
        }) {
    const std::vector<std::string> peers{"fdm"};
    hub_.accept(peers, "run-serve-test");
  }

  /// A solver still serving is shut down, so that it does not wait out its idle timeout.
  ~ServedFdm() {
    if (stopped_) return;
    try {
      shut_down();
    } catch (const Error&) {
      // The test has failed already; the solver stops at its idle timeout.
    }
  }
  ServedFdm(const ServedFdm&) = delete;
  ServedFdm& operator=(const ServedFdm&) = delete;

  cosim::Hub& hub() { return hub_; }

  /// Sends a request and returns the reply; an Error reply is thrown as mpfd::Error.
  cosim::Message request(cosim::Message&& message) {
    hub_.send("fdm", std::move(message));
    return hub_.receive_from("fdm");
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

  void shut_down() {
    cosim::Message message;
    message.header.mutable_shutdown()->set_reason("test done");
    last_shutdown_ = request(std::move(message)).header.shutdown_ack();
    stopped_ = true;
  }
  const v1::ShutdownAck& last_shutdown() const { return last_shutdown_; }

 private:
  static cosim::TransportOptions options() {
    cosim::TransportOptions options;
    options.reply_timeout = std::chrono::milliseconds{5000};
    options.idle_timeout = std::chrono::milliseconds{5000};
    return options;
  }

  zmq::context_t context_;
  cosim::Hub hub_;
  cosim::testing::SolverThread solver_;  // last: joined before the hub closes
  v1::ShutdownAck last_shutdown_;
  bool stopped_ = false;
};

}  // namespace mpfd::fdm::testing
