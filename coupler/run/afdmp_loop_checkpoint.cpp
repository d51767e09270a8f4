// AfdmpLoop's checkpoint and restart (afdmp_loop.hpp, coupler_checkpoint.hpp): which
// solvers write one in each phase, the coupler's own state (with the 1D stage's
// particles while it runs), and going on from it, checked before anything changes.
#include <string>

#include "common/core/log.hpp"
#include "coupler/run/afdmp_loop.hpp"
#include "coupler/run/session.hpp"

namespace mpfd::coupler {

/// A restarted run: the coupler's state from `from`, checked, then each solver's
/// Restore, the solvers retired before it retired again, and gauges.csv as the
/// checkpoint had it. Nothing in the folder changes before the checks pass.
RunPosition AfdmpLoop::resume(const CouplerCheckpoint& from) {
  // Retired before the checkpoint; this run's solvers are shut down only once it is restored
  // (a refused restart shuts down every solver it started).
  std::set<std::string> retired;
  from.read_state([&](const RestartReader& in) {
    retired = restore(in);
    for (const auto& [peer, checkpoint] :
         {std::pair{"fdm", from.fdm}, std::pair{"mpm", from.mpm}}) {
      const std::string name = peer;
      if (checkpoint.has_value() != checkpointed(name, retired))
        in.refuse("names " + std::string(checkpoint ? "a" : "no") + " checkpoint of solver '" +
                  name + "', which " +
                  (retired.contains(name)        ? "was retired"
                   : checkpointed(name, retired) ? "holds state"
                                                 : "holds only its Setup's state") +
                  " in phase " + std::string(phase_name(machine_.phase())) + " (attribute " + name +
                  "_path, /afdmp/" + name + "_retired, /phases)");
    }
  });
  restore_solvers(hub_, from, options_.handoff_timeout);
  report_.steps = from.step;
  report_.time = from.time;
  for (const auto& peer : kAfdmpPeers)
    if (retired.contains(peer))
      retire(peer, "retired before the checkpoint this run restarts from");
  gauges_.resume_files();
  for (const auto& peer : kAfdmpPeers) contact_[peer] = Clock::now();
  hub_.set_clock(static_cast<std::uint64_t>(from.step), from.time);
  checkpoints_.restarted(from);
  Logger("coupler").info("restarted from ", from.file.string(), ": phase ",
                         phase_name(machine_.phase()), ", step ", from.step, ", t = ", from.time,
                         " s, ", from.outputs, " outputs written");
  return from.position();
}

/// Whether `peer` writes a checkpoint now, with `retired` shut down: not once retired, and
/// not the FDM before the blast is handed to it (in the MPM detonation and the 1D stage
/// it holds only its Setup's state, which a restart's Setup makes again).
bool AfdmpLoop::checkpointed(const std::string& peer, const std::set<std::string>& retired) const {
  const AfdmpPhase phase = machine_.phase();
  const bool before_fdm =
      phase == AfdmpPhase::mpm_detonation || phase == AfdmpPhase::spherical_detonation;
  return !retired.contains(peer) && !(peer == "fdm" && before_fdm);
}

/// Each solver that holds state checkpoints, then the coupler's file (with the 1D stage's
/// particles while it runs) is renamed into place last.
void AfdmpLoop::checkpoint(const RunPosition& at, double wall) {
  std::vector<std::string> peers;
  for (const auto& peer : kAfdmpPeers)
    if (checkpointed(peer, retired_)) peers.push_back(peer);
  const auto taken =
      take_checkpoint(hub_, at, wall, options_.out_dir, peers, options_.handoff_timeout,
                      scene_text_, grid_dimension(scene_), [&](RestartWriter& out) { save(out); });
  for (const auto& peer : peers) contact_[peer] = Clock::now();
  checkpoints_.taken(taken);
}

void AfdmpLoop::save(RestartWriter& out) const {
  out.number("afdmp", "dt", dt_);
  out.number("afdmp", "fdm_retired", retired_.contains("fdm") ? 1 : 0);
  out.number("afdmp", "mpm_retired", retired_.contains("mpm") ? 1 : 0);
  save_conserved(out, "afdmp", "placeholder", placeholder_);
  out.text("afdmp", "phases", phases_.dump());
  out.text("afdmp", "transitions", transitions_.dump());
  out.text("afdmp", "handoffs", handoffs_.dump());
  out.text("afdmp", "outputs", outputs_.dump());
  out.number("afdmp", "phase_time", phase_time_);
  out.number("afdmp", "phase_steps", static_cast<double>(phase_steps_));
  out.number("afdmp", "phase_wall_seconds", seconds_since(phase_start_));
  // What the solvers offered decides the audit's outflow and the handoffs' material import.
  out.feature("afdmp", "fdm_outflow", outflow_.fdm);
  out.feature("afdmp", "mpm_outflow", outflow_.mpm);
  out.feature("afdmp", "fdm_material_import", settings_.material_import);
  machine_.save(out);
  audit_.save(out);
  gauges_.save(out);
  if (holder_ == "spherical") stage_->save(out);
}

/// The coupler's state from `in`; returns the solvers retired before the checkpoint.
std::set<std::string> AfdmpLoop::restore(const RestartReader& in) {
  dt_ = in.number("afdmp", "dt");
  std::set<std::string> retired;
  for (const auto& peer : kAfdmpPeers)
    if (in.number("afdmp", peer + "_retired") != 0) retired.insert(peer);
  placeholder_ = restored_conserved(in, "afdmp", "placeholder");
  phases_ = in.json("afdmp", "phases");
  transitions_ = in.json("afdmp", "transitions");
  handoffs_ = in.json("afdmp", "handoffs");
  outputs_ = in.json("afdmp", "outputs");
  phase_time_ = in.number("afdmp", "phase_time");
  phase_steps_ = static_cast<std::int64_t>(in.number("afdmp", "phase_steps"));
  phase_start_ =
      Clock::now() - std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(in.number("afdmp", "phase_wall_seconds")));
  in.expect_feature("afdmp", "fdm_outflow", outflow_.fdm);
  in.expect_feature("afdmp", "mpm_outflow", outflow_.mpm);
  in.expect_feature("afdmp", "fdm_material_import", settings_.material_import);
  machine_.restore(in);
  // The phase names who holds the state (a run is never checkpointed once done).
  const AfdmpPhase phase = machine_.phase();
  holder_ = phase == AfdmpPhase::spherical_detonation ? "spherical"
            : phase == AfdmpPhase::fdm_blast          ? "fdm"
                                                      : "mpm";
  audit_.restore(in);
  gauges_.restore(in);
  if (holder_ == "spherical") {
    stage_.emplace(scene_);
    stage_->restore(in);
  }
  return retired;
}

}  // namespace mpfd::coupler
