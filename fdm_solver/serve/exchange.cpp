#include "fdm_solver/serve/exchange.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/core/require.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/gauge_sampler.hpp"
#include "fdm_solver/serve/region_transfer.hpp"

namespace mpfd::fdm {
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
  cosim::v1::AdvanceResult result;
  result.set_time(zone.time());
  result.set_wall_seconds(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return result;
}

}  // namespace

cosim::Message run_exchange(ServedZone& zone, const cosim::Message& request) {
  cosim::Message reply;
  auto& results = *reply.header.mutable_exchange_result();
  for (const auto& op : request.header.exchange().operations()) {
    auto& result = *results.add_results();
    switch (op.op_case()) {
      case cosim::v1::Operation::kApply:
        apply_region(zone.solver, zone.region(op.apply().region(), "ApplyRegion"),
                     op.apply().mode(), request);
        result.set_applied(true);
        break;
      case cosim::v1::Operation::kExportRegion: {
        if (const TracerRegion* tracers = zone.tracer_region(op.export_region().region())) {
          const auto& asked = op.export_region().quantities();
          const std::vector<std::string> names(asked.begin(), asked.end());
          result.mutable_exported()->set_region(tracers->name);
          result.mutable_exported()->set_count(export_tracers(zone.solver, *tracers, names, reply));
          break;
        }
        const auto& region = zone.region(op.export_region().region(), "ExportRegion");
        result.mutable_exported()->set_region(region.name);
        result.mutable_exported()->set_count(
            export_region(zone.solver, region, op.export_region(), reply));
        break;
      }
      case cosim::v1::Operation::kAdvance:
        *result.mutable_advanced() = advance(zone, op.advance());
        break;
      case cosim::v1::Operation::kProposeDt:
        result.mutable_proposed()->set_stable_dt(zone.solver.stable_dt());
        result.mutable_proposed()->set_limited_by("cfl");
        break;
      case cosim::v1::Operation::kSample:
        result.mutable_sampled()->set_group(op.sample().group());
        result.mutable_sampled()->set_count(sample_gauges(zone.solver, op.sample(), reply));
        break;
      case cosim::v1::Operation::kInject:
      case cosim::v1::Operation::kRemove:
        throw cosim::ProtocolError(
            cosim::v1::ERROR_CODE_UNEXPECTED,
            "Exchange operation " + std::to_string(results.results_size()) +
                ": InjectParticles and RemoveParticles are for MPM zones, not "
                "fdm_solver");
      case cosim::v1::Operation::OP_NOT_SET:
        throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                                   "Exchange operation " + std::to_string(results.results_size()) +
                                       " has no operation set");
    }
  }
  return reply;
}

}  // namespace mpfd::fdm
