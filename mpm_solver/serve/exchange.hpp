#pragma once
// One coupled step (proto/README.md §6): the operations of an Exchange run
// in order on the served MPM zone, one result each.

#include "cosim/message.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

/// Two times agree when they differ by at most this fraction of the larger
/// of them and dt (as fdm_solver serve: summing 10^6 steps drifts ~10^-10).
inline constexpr double kTimeTolerance = 1e-9;

/// Runs ApplyRegion, InjectParticles, Advance, ExportRegion, RemoveParticles,
/// ProposeDt and SampleGauges in the order given; returns the ExchangeResult
/// with the exported, removed and sampled arrays. Throws ProtocolError:
/// UNKNOWN_REGION, MALFORMED, UNEXPECTED (a dormant zone, or Advance from
/// another time than the solver's) or NUMERICAL (the solver broke down).
[[nodiscard]] cosim::Message run_exchange(ServedZone& zone, const cosim::Message& request);

}  // namespace mpfd::mpm
