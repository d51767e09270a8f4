#pragma once
// A stand-in for `mpm_solver serve` in coupler tests (until the real one is
// merged): an MPM zone of ideal gas at rest, uniform density and pressure,
// answering the operations of proto §6 with the values a real MPM would give
// for that state (nodal mass ρV_c per node, internal energy pV_c/(γ-1) per
// ghost cell, 2 particles per zone cell). It counts the mass injected into it.
// `silent_from_step`: from that step on it stops answering (a hung solver).
// `fatal_at_step`: at that step it answers a fatal NUMERICAL Error, then stays
// connected and silent for `linger_ms` (a solver process still tearing down).
// It counts the requests it gets between Setup and Shutdown and answers Activate
// (a dormant zone), noting the Activate's sim_time. `advance_wall_seconds` is the
// wall time its AdvanceResult reports (0: faster than any FDM).

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "cosim/arrays.hpp"
#include "cosim/participant.hpp"

namespace mpfd::coupler::testing {

/// The scene the stand-in is made for: air (1.2 kg/m^3, 1e5 Pa) in a closed
/// 1 m tube of 40 cells, FDM [0, 0.6], MPM [0.4, 1], w = 5 cells, outputs at
/// end / 2; `mpm_keys` (", key: value") are added to zones.mpm.
inline std::string still_tube_scene(const std::string& name, double end,
                                    const std::string& mpm_keys = "") {
  return "name: " + name + "\ntime: {end: " + std::to_string(end) +
         ", cfl: 0.5}\n"
         "domain: {lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [40, 1, 1]}\n"
         "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
         "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
         "boundaries: {x_lower: wall, x_upper: wall}\n"
         "output: {interval: " +
         std::to_string(end / 2) +
         "}\nsolver: {method: cfdmp}\n"
         "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.6, 0.01, 0.01]}\n"
         "  mpm: {lower: [0.4, 0, 0], upper: [1, 0.01, 0.01]" +
         mpm_keys + "}\n  handshake_width: 5\n";
}

struct StillMpm {
  double density = 1.2;
  double pressure = 1.0e5;
  double gamma = 1.4;
  double cell_volume = 0;
  std::int64_t silent_from_step = -1;
  std::int64_t fatal_at_step = -1;
  int linger_ms = 0;
  std::atomic<double> injected_mass{0};
  std::atomic<int> requests_after_setup{0};  ///< every request but Setup and Shutdown
  std::atomic<double> activated_at{-1};      ///< sim_time of the Activate [s]; -1: none
  int idle_timeout_ms = 10000;               ///< how long it waits for a request
  double advance_wall_seconds = 0;           ///< AdvanceResult.wall_seconds it reports
  /// Its face-cell particles (face_particles, 2 per cell): material index, density
  /// [kg/m^3] (< 0: `density`) and, when asked for it, volume [m^3] (< 0: half a cell).
  std::uint32_t face_material = 0;
  double face_density = -1;
  double face_volume = -1;
  std::atomic<bool> shut_down{false};  ///< it got Shutdown (was still serving)
};

inline std::int64_t box_count(const cosim::v1::IndexBox& box, int shrink_active_by,
                              int active_axis) {
  std::int64_t n = 1;
  for (int a = 0; a < box.lo_size(); ++a)
    n *= box.hi(a) - box.lo(a) - (a == active_axis ? shrink_active_by : 0);
  return n;
}

/// Serves one session on `endpoint` as "mpm" (1D scenes along x).
inline void serve_still_mpm(zmq::context_t& context, const std::string& endpoint, StillMpm& mpm) {
  namespace v1 = cosim::v1;
  cosim::TransportOptions transport;
  transport.idle_timeout = std::chrono::milliseconds(mpm.idle_timeout_ms);
  cosim::Participant participant(context, endpoint, "mpm", transport);
  v1::Hello hello;
  hello.set_role(v1::ROLE_MPM_SOLVER);
  hello.set_software("still_mpm (test)");
  hello.set_min_major(1);
  hello.set_max_major(1);
  participant.connect(hello);
  std::map<std::string, v1::Region> regions;
  double time = 0;
  while (true) {
    cosim::Message request = participant.receive();
    cosim::Message reply;
    const auto& header = request.header;
    if (header.has_shutdown()) {
      mpm.shut_down = true;
      reply.header.mutable_shutdown_ack();
      participant.reply(request, std::move(reply));
      return;
    }
    if (!header.has_setup()) ++mpm.requests_after_setup;
    if (header.has_activate()) {
      mpm.activated_at = header.envelope().sim_time();
      reply.header.mutable_activate_ack()->set_stable_dt(1.0);
    } else if (header.has_setup()) {
      for (const auto& r : header.setup().regions()) regions[r.name()] = r;
      *reply.header.mutable_setup_ack()->mutable_regions() = header.setup().regions();
      reply.header.mutable_setup_ack()->set_stable_dt(1.0);
    } else if (header.has_write_output()) {
      reply.header.mutable_output_written();
    } else if (header.has_exchange()) {
      if (mpm.silent_from_step >= 0 &&
          static_cast<std::int64_t>(header.envelope().step()) >= mpm.silent_from_step)
        continue;
      if (static_cast<std::int64_t>(header.envelope().step()) == mpm.fatal_at_step) {
        participant.send_error(&request, v1::ERROR_CODE_NUMERICAL,
                               "mpm: unphysical state of particle 0 (test)");
        std::this_thread::sleep_for(std::chrono::milliseconds(mpm.linger_ms));
        return;
      }
      for (const auto& op : header.exchange().operations()) {
        auto& result = *reply.header.mutable_exchange_result()->add_results();
        if (op.has_apply()) {
          result.set_applied(true);
        } else if (op.has_inject()) {
          const auto m = cosim::view_array<double>(request, op.inject().group(), "mass");
          double sum = 0;
          for (const double v : m.values()) sum += v;
          mpm.injected_mass = mpm.injected_mass + sum;
          result.mutable_injected()->set_injected(m.values().size());
        } else if (op.has_advance()) {
          time = op.advance().time() + op.advance().dt();
          result.mutable_advanced()->set_time(time);
          result.mutable_advanced()->set_wall_seconds(mpm.advance_wall_seconds);
        } else if (op.has_remove()) {
          result.mutable_removed()->set_group(op.remove().group());
        } else if (op.has_propose_dt()) {
          result.mutable_proposed()->set_stable_dt(1.0);
        } else if (op.has_export_region()) {
          const std::string& name = op.export_region().region();
          const auto& box = regions.at(name).box();
          const double e = mpm.pressure / (mpm.gamma - 1) * mpm.cell_volume;
          result.mutable_exported()->set_region(name);
          if (name == "ghost_nodes") {
            const auto nodes = static_cast<std::size_t>(box_count(box, 0, 0));
            const auto cells = static_cast<std::size_t>(box_count(box, 1, 0));
            result.mutable_exported()->set_count(nodes);
            cosim::add_array(reply, {name, "mass", {}, "kg"},
                             std::vector<double>(nodes, mpm.density * mpm.cell_volume));
            cosim::add_array(reply, {name, "momentum", {nodes, 3}, "kg*m/s"},
                             std::vector<double>(3 * nodes, 0.0));
            cosim::add_array(reply, {name, "internal_energy", {}, "J"},
                             std::vector<double>(cells, e));
          } else if (name == "face_particles") {  // 2 per cell; 1D: the one face cell holds them
            const auto n = static_cast<std::size_t>(2 * box_count(box, 0, 0));
            result.mutable_exported()->set_count(n);
            const double rho = mpm.face_density < 0 ? mpm.density : mpm.face_density;
            cosim::add_array(reply, {name, "mass", {}, "kg"},
                             std::vector<double>(n, 0.5 * rho * mpm.cell_volume));
            cosim::add_array(reply, {name, "position", {n, 3}, "m"},
                             std::vector<double>(3 * n, 0.0));
            const auto& asked = op.export_region().quantities();
            if (std::find(asked.begin(), asked.end(), "volume") != asked.end()) {
              cosim::add_array(reply, {name, "volume", {}, "m^3"},
                               std::vector<double>(n, mpm.face_volume < 0 ? 0.5 * mpm.cell_volume
                                                                          : mpm.face_volume));
              cosim::add_array(reply, {name, "material", {}, "1"},
                               std::vector<std::uint32_t>(n, mpm.face_material));
            }
          } else {  // mpm_zone: 2 particles per cell
            const auto n = static_cast<std::size_t>(2 * box_count(box, 0, 0));
            result.mutable_exported()->set_count(n);
            cosim::add_array(reply, {name, "mass", {}, "kg"},
                             std::vector<double>(n, 0.5 * mpm.density * mpm.cell_volume));
            cosim::add_array(reply, {name, "velocity", {n, 3}, "m/s"},
                             std::vector<double>(3 * n, 0.0));
            cosim::add_array(reply, {name, "internal_energy", {}, "J"},
                             std::vector<double>(n, 0.5 * e));
          }
        }
      }
    }
    participant.reply(request, std::move(reply));
  }
}

}  // namespace mpfd::coupler::testing
