#include "mpm_solver/serve/exchange.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/core/require.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "mpm_solver/serve/gauge_sampler.hpp"
#include "mpm_solver/serve/node_transfer.hpp"
#include "mpm_solver/serve/particle_transfer.hpp"

namespace mpfd::mpm {
namespace {

cosim::v1::AdvanceResult advance(ServedZone& zone, const cosim::v1::Advance& op) {
  const double dt = op.dt();
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_MALFORMED,
        "Advance dt must be positive and finite, got " + shortest_text(dt) + " s");
  const double now = zone.time();
  if (std::abs(op.time() - now) >
      kTimeTolerance * std::max({std::abs(op.time()), std::abs(now), dt}))
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNEXPECTED,
                               "Advance from time " + shortest_text(op.time()) +
                                   " s, but the solver is at " + shortest_text(now) + " s (after " +
                                   std::to_string(zone.solver.steps()) + " steps)");
  const auto start = std::chrono::steady_clock::now();
  try {
    zone.solver.advance(dt);
  } catch (const Error& error) {
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_NUMERICAL, error.what());
  }
  // The step's own work: with it, the scatter a ghost-node export did for it early.
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (zone.solver.last_advance_was_premapped()) seconds += zone.next_step_map_seconds;
  zone.next_step_map_seconds = 0.0;
  cosim::v1::AdvanceResult result;
  result.set_time(zone.time());
  result.set_wall_seconds(seconds);
  return result;
}

}  // namespace

cosim::Message run_exchange(ServedZone& zone, const cosim::Message& request) {
  if (zone.dormant)
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_UNEXPECTED,
        "Exchange to a dormant MPM zone; send Activate first (proto/README.md §5)");
  cosim::Message reply;
  auto& results = *reply.header.mutable_exchange_result();
  MpmSolver& solver = zone.solver;
  for (const auto& op : request.header.exchange().operations()) {
    auto& result = *results.add_results();
    switch (op.op_case()) {
      case cosim::v1::Operation::kApply:
        apply_node_region(solver, zone.region(op.apply().region(), "ApplyRegion"),
                          op.apply().mode(), request);
        result.set_applied(true);
        break;
      case cosim::v1::Operation::kInject:
        result.mutable_injected()->set_injected(inject_particles(solver, op.inject(), request));
        break;
      case cosim::v1::Operation::kExportRegion: {
        const auto& region = zone.region(op.export_region().region(), "ExportRegion");
        result.mutable_exported()->set_region(region.name);
        result.mutable_exported()->set_count(
            region.kind == cosim::v1::REGION_KIND_NODES
                ? export_node_region(solver, region, op.export_region(), zone.node_box_map,
                                     &zone.next_step_map_seconds, reply)
                : export_particle_region(solver, region, op.export_region(), reply,
                                         zone.particle_scratch));
        break;
      }
      case cosim::v1::Operation::kRemove: {
        const auto& remove = op.remove();
        const ZoneRegion* left = remove.left_region().empty()
                                     ? nullptr
                                     : &zone.region(remove.left_region(), "RemoveParticles");
        result.mutable_removed()->set_group(remove.group());
        result.mutable_removed()->set_removed(
            remove_particles(solver, left, remove, request, reply, zone.particle_scratch));
        break;
      }
      case cosim::v1::Operation::kAdvance:
        *result.mutable_advanced() = advance(zone, op.advance());
        break;
      case cosim::v1::Operation::kProposeDt:
        result.mutable_proposed()->set_stable_dt(solver.stable_dt());
        result.mutable_proposed()->set_limited_by("cfl");
        break;
      case cosim::v1::Operation::kSample:
        result.mutable_sampled()->set_group(op.sample().group());
        result.mutable_sampled()->set_count(
            sample_gauges(solver, zone.followed_gauges, op.sample(), reply));
        break;
      case cosim::v1::Operation::OP_NOT_SET:
        throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                                   "Exchange operation " +
                                       std::to_string(results.results_size() - 1) +
                                       " has no operation set");
    }
  }
  return reply;
}

}  // namespace mpfd::mpm
