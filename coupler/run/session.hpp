#pragma once
// What every coupled run (CFDMP, AFDMP) does the same way with its solvers:
// a run id, the scene's grid on the wire, capabilities from Hello, advance
// times from replies, and the best-effort Shutdown at the end.

#include <chrono>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "common/config/scene.hpp"
#include "common/io/run_summary.hpp"
#include "cosim/hub.hpp"
#include "coupler/run/coupled_run.hpp"
#include "coupler/run/solver_handle.hpp"

namespace mpfd::coupler {

namespace v1 = cosim::v1;

/// Wall seconds since `start` (phase, handoff and step timings in summary.json).
[[nodiscard]] inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A coupled step from t: `dt`, or the rest up to `next_output` when dt would reach
/// it (within a relative 1e-12: no sliver step before an output).
struct StepToOutput {
  double dt;
  bool output_now;
};
[[nodiscard]] inline StepToOutput step_to_output(double t, double dt, double next_output) {
  if (t + dt >= next_output * (1 - 1e-12)) return {next_output - t, true};
  return {dt, false};
}

/// 16 hex digits, new for every run (proto §5: HelloAck.run_id).
[[nodiscard]] std::string make_run_id();

/// The axes of the scene's grid with more than one cell.
[[nodiscard]] int grid_dimension(const config::Scene& scene);

/// The scene's whole grid as a Setup zone grid (dimension: grid_dimension).
[[nodiscard]] v1::UniformGrid wire_grid(const config::Scene& scene);

/// True when the solver's Hello lists `capability`.
[[nodiscard]] bool offers(const v1::Hello& hello, std::string_view capability);

/// AdvanceResult.wall_seconds of an ExchangeResult, 0 if it holds no Advance.
[[nodiscard]] double advance_seconds(const cosim::Message& reply);

/// Best effort: Shutdown to every solver still there (not in `already_shut`),
/// then end the ones we started. Returns how each ended ("; solver 'fdm' ...").
std::string shut_down(cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                      const std::string& reason, const std::set<std::string>& already_shut = {});

/// What a run does between accepting its solvers and shutting them down: gets
/// their Hellos (in the order "fdm", "mpm") and the summary to fill; adds to
/// `retired` every solver it has already shut down.
using SessionBody = std::function<CoupledRunReport(
    const std::vector<v1::Hello>& hellos, io::RunSummary& summary, std::set<std::string>& retired)>;

/// The frame every coupled run shares: the recording (options.record), the
/// output folders, Hello from both solvers (logged), then `body`. On any
/// failure: names the solvers that ended and how, writes summary.json with
/// status "failed", shuts the others down, closes the recording and throws
/// mpfd::Error "coupler run failed: ...". On success: shuts the solvers down.
CoupledRunReport run_session(const config::Scene& scene, cosim::Hub& hub,
                             std::vector<std::unique_ptr<SolverHandle>>& solvers,
                             const CoupledRunOptions& options, const SessionBody& body);

}  // namespace mpfd::coupler
