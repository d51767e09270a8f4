#pragma once
// What every coupled run (CFDMP, AFDMP) does the same way with its solvers:
// a run id, the scene's grid on the wire, capabilities from Hello, advance
// times from replies, and the best-effort Shutdown at the end.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "common/config/scene.hpp"
#include "cosim/hub.hpp"
#include "coupler/run/solver_handle.hpp"

namespace mpfd::coupler {

namespace v1 = cosim::v1;

/// 16 hex digits, new for every run (proto §5: HelloAck.run_id).
[[nodiscard]] std::string make_run_id();

/// The scene's whole grid as a Setup zone grid (dimension = axes with more than one cell).
[[nodiscard]] v1::UniformGrid wire_grid(const config::Scene& scene);

/// True when the solver's Hello lists `capability`.
[[nodiscard]] bool offers(const v1::Hello& hello, std::string_view capability);

/// AdvanceResult.wall_seconds of an ExchangeResult, 0 if it holds no Advance.
[[nodiscard]] double advance_seconds(const cosim::Message& reply);

/// Best effort: Shutdown to every solver still there, then end the ones we
/// started. Returns how each ended ("; solver 'fdm' exited with code 0 ...").
std::string shut_down(cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                      const std::string& reason);

}  // namespace mpfd::coupler
