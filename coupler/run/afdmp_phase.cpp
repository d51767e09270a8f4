#include "coupler/run/afdmp_phase.hpp"

#include <algorithm>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler {

std::string_view phase_name(AfdmpPhase phase) {
  switch (phase) {
    case AfdmpPhase::mpm_detonation:
      return "mpm_detonation";
    case AfdmpPhase::spherical_detonation:
      return "spherical_detonation";
    case AfdmpPhase::fdm_blast:
      return "fdm_blast";
    case AfdmpPhase::mpm_fsi:
      return "mpm_fsi";
    case AfdmpPhase::done:
      break;
  }
  return "done";
}

std::string_view trigger_name(AfdmpTrigger trigger) {
  switch (trigger) {
    case AfdmpTrigger::burn_complete:
      return "burn_complete";
    case AfdmpTrigger::front_radius:
      return "front_radius";
    case AfdmpTrigger::pressure:
      return "pressure";
    case AfdmpTrigger::end_time:
      break;
  }
  return "end_time";
}

nlohmann::json Transition::summary() const {
  return {{"from", phase_name(from)},
          {"to", phase_name(to)},
          {"trigger", trigger_name(trigger)},
          {"time", time},
          {"step", step},
          {"value", value},
          {"threshold", threshold}};
}

PhaseMachine::PhaseMachine(const PhaseSettings& settings)
    : settings_(settings),
      phase_(settings.start == AfdmpStart::mpm ? AfdmpPhase::mpm_detonation
                                               : AfdmpPhase::spherical_detonation),
      watch_(settings.fsi_zone ? settings.activation_pressure : std::nullopt) {
  require(settings.end_time > 0.0, "afdmp phases", "time.end", settings.end_time, "> 0 s");
  if (settings.fsi_zone && !settings.activation_pressure)
    throw Error("afdmp phases: an FSI zone needs zones.mpm.activation_pressure [Pa]");
  if (settings.start == AfdmpStart::spherical)
    require(settings.handoff_radius > 0.0, "afdmp phases", "solver.afdmp.spherical.handoff_radius",
            settings.handoff_radius, "> 0 m");
}

bool PhaseMachine::needs_fluid_burn_check(const BurnObservation& charge_burn) const {
  return explosive_at_start_ && charge_burn.explosive_particles < *explosive_at_start_;
}

std::optional<Transition> PhaseMachine::next(const Observation& observation) {
  if (phase_ == AfdmpPhase::done) return std::nullopt;
  // As the CFDMP loop (coupled_run.cpp): the last step lands on time.end.
  if (observation.time >= settings_.end_time * (1 - 1e-12))
    return move_to(AfdmpPhase::done, AfdmpTrigger::end_time, observation, observation.time,
                   settings_.end_time);
  return trigger(observation);
}

std::optional<Transition> PhaseMachine::trigger(const Observation& o) {
  const auto missing = [&](const char* input) {
    return Error("afdmp phase " + std::string(phase_name(phase_)) + " at step " +
                 std::to_string(o.step) + ": the observation lacks " + input);
  };
  switch (phase_) {
    case AfdmpPhase::mpm_detonation: {
      if (!o.charge_burn) throw missing("the charge_particles burn state");
      if (!explosive_at_start_) explosive_at_start_ = o.charge_burn->explosive_particles;
      const BurnObservation* burn = &*o.charge_burn;
      if (needs_fluid_burn_check(*o.charge_burn)) {
        if (!o.fluid_burn)
          throw missing("the fluid_particles burn state (the charge box lost explosive particles)");
        burn = &*o.fluid_burn;
      }
      if (!burn->complete) return std::nullopt;
      return move_to(AfdmpPhase::fdm_blast, AfdmpTrigger::burn_complete, o,
                     static_cast<double>(burn->explosive_particles), 0.0);
    }
    case AfdmpPhase::spherical_detonation: {
      if (!o.spherical_burn_complete || !o.front_radius)
        throw missing("the 1D burn state and front radius");
      if (!*o.spherical_burn_complete || *o.front_radius < settings_.handoff_radius)
        return std::nullopt;
      return move_to(AfdmpPhase::fdm_blast, AfdmpTrigger::front_radius, o, *o.front_radius,
                     settings_.handoff_radius);
    }
    case AfdmpPhase::fdm_blast: {
      if (!settings_.fsi_zone) return std::nullopt;
      if (o.watch_pressure.empty()) throw missing("the fsi_watch pressure");
      watch_.observe(o.watch_pressure, o.time);
      if (!watch_.due()) return std::nullopt;
      watch_.activated(o.time, o.step);
      const double peak = *std::max_element(o.watch_pressure.begin(), o.watch_pressure.end());
      return move_to(AfdmpPhase::mpm_fsi, AfdmpTrigger::pressure, o, peak,
                     *settings_.activation_pressure);
    }
    case AfdmpPhase::mpm_fsi:
    case AfdmpPhase::done:
      break;
  }
  return std::nullopt;
}

void PhaseMachine::save(RestartWriter& out) const {
  out.number("phases", "phase", static_cast<double>(phase_));
  out.optional_number(
      "phases", "explosive_at_start",
      explosive_at_start_ ? std::optional<double>(*explosive_at_start_) : std::nullopt);
  watch_.save(out);
}

void PhaseMachine::restore(const RestartReader& in) {
  const double phase = in.number("phases", "phase");
  if (!(phase >= 0 && phase <= static_cast<double>(AfdmpPhase::done)))
    in.refuse("holds phase " + std::to_string(phase) + "; expected 0 ... " +
              std::to_string(static_cast<int>(AfdmpPhase::done)));
  const auto explosive = in.optional_number("phases", "explosive_at_start");
  watch_.restore(in);
  phase_ = static_cast<AfdmpPhase>(static_cast<int>(phase));
  explosive_at_start_.reset();
  if (explosive) explosive_at_start_ = static_cast<std::size_t>(*explosive);
}

Transition PhaseMachine::move_to(AfdmpPhase to, AfdmpTrigger why, const Observation& observation,
                                 double value, double threshold) {
  Transition t{phase_, to, why, observation.time, observation.step, value, threshold};
  phase_ = to;
  return t;
}

}  // namespace mpfd::coupler
