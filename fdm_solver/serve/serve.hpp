#pragma once
// `fdm_solver serve`: the solver side of protocol v1 (proto/README.md) for
// the FDM Euler solver. Connects to a coupler, then answers its requests one
// by one until Shutdown.

#include <chrono>
#include <string>
#include <zmq.hpp>

namespace mpfd::fdm {

struct ServeOptions {
  std::string endpoint;      ///< the coupler's ROUTER: ipc://, tcp://, inproc://
  std::string name = "fdm";  ///< routing id the coupler knows this solver by
  std::chrono::milliseconds idle_timeout{60000};  ///< longest wait for the coupler's next request
  /// Offer only protocol v1.0's capabilities (no face_crossing, boundary_outflow):
  /// behaves as a solver written against v1.0, for comparisons and fallback tests.
  bool offer_v1_0_only = false;
  /// Offer boundary_outflow (v1.1): off, a coupler must treat the solver's outflow
  /// as v1.0 (0), for fallback tests of the run-long audits.
  bool offer_boundary_outflow = true;
  /// Offer material_import (v1.2): off, a coupler must send cells without each
  /// material's start, for fallback tests of the AFDMP handoff.
  bool offer_material_import = true;
};

/// Sends Hello, then answers Setup, Exchange, WriteOutput, Checkpoint,
/// Restore, Activate and Ping until Shutdown, which it acknowledges and
/// returns from. Field handoffs get a non-fatal Error{UNEXPECTED}; a
/// Checkpoint or Restore that fails gets a non-fatal Error and leaves the
/// state as it was (checkpoint.hpp). Throws mpfd::Error —
/// after answering the request with a fatal Error{code, message} — when the
/// coupler refuses the version, stays silent for idle_timeout, or sends a
/// request that cannot be carried out, and when the solver breaks down.
void serve(zmq::context_t& context, const ServeOptions& options);

}  // namespace mpfd::fdm
