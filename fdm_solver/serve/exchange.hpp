#pragma once
// One coupled step (proto/README.md §6): the operations of an Exchange run
// in order on the served zone, one result each.

#include "cosim/message.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// Two times agree when they differ by at most this fraction of the larger
/// of them and dt: summing 10^6 steps of dt in binary64 drifts by ~10^-10.
inline constexpr double kTimeTolerance = 1e-9;

/// Runs ApplyRegion, ExportRegion, Advance, ProposeDt and SampleGauges in the
/// order given; returns the ExchangeResult with the exported and sampled
/// arrays. Throws cosim::ProtocolError: UNKNOWN_REGION, MALFORMED, UNEXPECTED (a
/// particle operation, or Advance from another time than the solver's) or
/// NUMERICAL (the solver broke down; its message).
[[nodiscard]] cosim::Message run_exchange(ServedZone& zone, const cosim::Message& request);

}  // namespace mpfd::fdm
