#pragma once
// The AFDMP run loop of `coupler run` (afdmp_run.hpp): one solver is stepped at a
// time, the phase machine's transitions are handed over (afdmp_handoffs.hpp), and
// the run-long audit, the gauges, the outputs and the checkpoints follow the solver
// that holds the state. Its parts: afdmp_loop.cpp (steps and handoffs),
// afdmp_loop_output.cpp (outputs and summary.json), afdmp_loop_checkpoint.cpp
// (checkpoint and restart, coupler_checkpoint.hpp).

#include <chrono>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"
#include "common/io/run_summary.hpp"
#include "cosim/hub.hpp"
#include "coupler/run/afdmp_audit.hpp"
#include "coupler/run/afdmp_handoffs.hpp"
#include "coupler/run/afdmp_layout.hpp"
#include "coupler/run/afdmp_phase.hpp"
#include "coupler/run/coupled_run.hpp"
#include "coupler/run/coupler_checkpoint.hpp"
#include "coupler/run/gauges.hpp"
#include "coupler/run/restart_file.hpp"
#include "coupler/run/spherical_stage.hpp"

namespace mpfd::coupler {

/// The two solvers of an AFDMP run, in this order.
inline const std::vector<std::string> kAfdmpPeers = {"fdm", "mpm"};

/// The scene's solver.afdmp.start.
[[nodiscard]] AfdmpStart afdmp_start(const config::Scene& scene);

class AfdmpLoop {
 public:
  /// After both solvers' Setup: `layout` of `scene`, the solvers' audit outflow and
  /// material import (their Hello), `options` of `coupler run`.
  AfdmpLoop(const config::Scene& scene, const std::string& scene_text, const AfdmpLayout& layout,
            AuditOutflow outflow, bool material_import, cosim::Hub& hub, io::RunSummary& summary,
            const CoupledRunOptions& options);
  /// Runs (or, with options.restart, goes on) to the scene's end. Throws mpfd::Error.
  CoupledRunReport run();
  /// Writes summary.json with `status` after `wall` seconds (and gauges.h5).
  void record_summary(const std::string& status, double wall);
  /// False while a restart has not yet restored the run: its summary would hold nothing
  /// yet and must not replace the stopped run's files (gauges.h5 among them).
  [[nodiscard]] bool summary_ready() const { return checkpoints_.summary_ready(); }
  /// The peers that have not been shut down (for the final shutdown).
  [[nodiscard]] const std::set<std::string>& retired() const { return retired_; }

 private:
  using Clock = std::chrono::steady_clock;

  /// A new run: phase 1 (or the 1D stage) set up, the audit's start, output 0.
  RunPosition begin();
  /// A restarted run: the coupler's state from `from`, checked, then each solver's
  /// Restore, the solvers retired before it retired again, and gauges.csv as the
  /// checkpoint had it. Nothing in the folder changes before the checks pass.
  RunPosition resume(const CouplerCheckpoint& from);
  /// Whether `peer` writes a checkpoint now, with `retired` shut down: not once retired, and
  /// not the FDM before the blast is handed to it (in the MPM detonation and the 1D stage
  /// it holds only its Setup's state, which a restart's Setup makes again).
  [[nodiscard]] bool checkpointed(const std::string& peer,
                                  const std::set<std::string>& retired) const;
  /// Each solver that holds state checkpoints, then the coupler's file (with the 1D stage's
  /// particles while it runs) is renamed into place last.
  void checkpoint(const RunPosition& at, double wall);
  void save(RestartWriter& out) const;
  /// The coupler's state from `in`; returns the solvers retired before the checkpoint.
  [[nodiscard]] std::set<std::string> restore(const RestartReader& in);
  /// One step of the current phase from t to t_next.
  void step(double t, double t_next, std::int64_t n);
  /// Phase 1 by the MPM: advance (unless step 0), the charge's burn state, dt.
  void step_mpm_detonation(bool advance, double dt, double t);
  /// Phase 2 (fdm) or 3 (mpm): advance, the FSI-face watch (phase 2), gauges (phase 2's
  /// following gauges from the idle MPM), dt.
  void step_solver(const std::string& peer, double dt, double t, GaugeSamplers samplers);
  BurnObservation burn_observation(const cosim::Message& reply, const char* region_name) const;
  cosim::Message send_and_receive(const std::string& peer, cosim::Message& request);
  /// A transition due now: hand over, retire the solver without a further role.
  void handle(const std::optional<Transition>& transition, double t, std::int64_t n);
  /// The MPM keeps its FSI-zone particles; what lies outside them is the FDM's now.
  void discard_mpm_fluid();
  void retire(const std::string& peer, const std::string& reason);
  /// Pings every idle solver still needed whose last answer is older than keep_alive.
  void keep_idle_alive() { ping_idle(options_.keep_alive); }
  /// Pings every solver still needed, other than the active one, whose last answer is
  /// older than `age`.
  void ping_idle(std::chrono::milliseconds age);
  void observe_stage();
  void sample_stage_gauges(double t);
  /// The run-long audit's reading of `who` ("spherical", "fdm" or "mpm") now.
  void audit_holder(const std::string& who);
  /// Output of the solver that holds the state now (the last phase's, once done),
  /// and the run-long audit's reading of it.
  void write_output(int index);
  void write_solver_output(const std::string& peer, int index);
  /// The 1D stage's particles as CSV (radius, density, velocity, specific energy, material).
  void write_stage_profile(int index);
  const config::Scene& scene_;
  const std::string& scene_text_;
  const AfdmpLayout& layout_;
  AuditOutflow outflow_;
  AfdmpStart start_;
  PhaseMachine machine_;
  std::vector<int> explosive_;
  mutable std::vector<int> materials_;  ///< scratch of burn_observation, kept between steps
  CoupledGauges gauges_;
  cosim::Hub& hub_;
  io::RunSummary& summary_;
  const CoupledRunOptions& options_;
  HandoffSettings settings_;
  grid::UniformGrid grid_;  ///< the scene's
  RunLongAudit audit_;
  std::optional<SphericalStage> stage_;
  std::string holder_ = "mpm";  ///< who holds the state: "mpm", "spherical" or "fdm"
  Observation observation_;
  double dt_ = 0;
  cosim::Message fdm_request_, mpm_request_;
  std::map<std::string, Clock::time_point> contact_;
  std::set<std::string> retired_;
  Conserved placeholder_;
  std::vector<double> stage_pressure_;
  nlohmann::json phases_ = nlohmann::json::array();
  nlohmann::json transitions_ = nlohmann::json::array();
  nlohmann::json handoffs_ = nlohmann::json::array();
  nlohmann::json outputs_ = nlohmann::json::array();
  double phase_time_ = 0;
  std::int64_t phase_steps_ = 0;
  Clock::time_point phase_start_;
  CoupledRunReport report_;
  CheckpointLog checkpoints_{options_.checkpoint_every, options_.checkpoint_keep,
                             options_.restart.has_value()};
};

}  // namespace mpfd::coupler
