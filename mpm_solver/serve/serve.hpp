#pragma once
// `mpm_solver serve`: the solver side of protocol v1 (proto/README.md) for
// the MPM solver. Connects to a coupler, then answers its requests one by
// one until Shutdown.

#include <chrono>
#include <string>
#include <zmq.hpp>

namespace mpfd::mpm {

struct ServeOptions {
  std::string endpoint;      ///< the coupler's ROUTER: ipc://, tcp://, inproc://
  std::string name = "mpm";  ///< routing id the coupler knows this solver by
  std::chrono::milliseconds idle_timeout{60000};  ///< longest wait for the coupler's next request
};

/// Sends Hello, then answers Setup, Activate, Exchange, WriteOutput,
/// Checkpoint, Restore, the whole-field transfers of v1.2 (FieldExportRequest,
/// FieldChunk, FieldImportCommit) and Ping until Shutdown, which it
/// acknowledges and returns from. A refused field transfer gets a non-fatal
/// Error; a failed Checkpoint or Restore a non-fatal Error{IO}, the state
/// unchanged. Throws
/// mpfd::Error — after answering the request with a fatal Error{code,
/// message} — when the coupler refuses the version, stays silent for
/// idle_timeout, or sends a request that cannot be carried out, and when
/// the solver breaks down.
void serve(zmq::context_t& context, const ServeOptions& options);

}  // namespace mpfd::mpm
