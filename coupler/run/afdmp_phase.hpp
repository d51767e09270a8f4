#pragma once
// The AFDMP phases and their triggers (design §3.3), pure logic: the run loop
// reports what the step just done showed (an Observation) and the machine
// answers whether a handoff is due now, at that time (no extra advance).
//
//   start = mpm:       mpm_detonation --burn_complete--> fdm_blast
//   start = spherical: spherical_detonation --front_radius--> fdm_blast
//   fdm_blast --pressure (FSI zone only)--> mpm_fsi
//   any phase: t >= time.end --> done
//
// burn_complete: handoff::detonation_complete on the charge_particles export
// (T §3.2.1). Safeguard: an unlit explosive particle pushed out of the charge
// box would make it vacuously true, so while the box holds fewer explosive
// particles than at the first observation the check must be made on the
// fluid_particles export instead (the loop asks needs_fluid_burn_check()).
// front_radius: every explosive particle of the 1D MPM burnt (F = 1) and the
// shock front at or beyond solver.afdmp.spherical.handoff_radius.
// pressure: the largest fsi_watch pressure passes zones.mpm.activation_pressure
// (absolute, T §3.2.3), through CFDMP's ActivationWatch (activation.hpp).
// The first observation is the one of step 0: a trigger true there hands off
// at t = 0 (an instantaneous burn, a threshold below ambient).

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <vector>

#include "coupler/run/activation.hpp"
#include "coupler/run/afdmp_layout.hpp"

namespace mpfd::coupler {

enum class AfdmpPhase { mpm_detonation, spherical_detonation, fdm_blast, mpm_fsi, done };
enum class AfdmpTrigger { burn_complete, front_radius, pressure, end_time };

/// "mpm_detonation", "spherical_detonation", "fdm_blast", "mpm_fsi", "done" (summary.json).
[[nodiscard]] std::string_view phase_name(AfdmpPhase phase);
/// "burn_complete", "front_radius", "pressure", "end_time".
[[nodiscard]] std::string_view trigger_name(AfdmpTrigger trigger);

struct PhaseSettings {
  AfdmpStart start = AfdmpStart::mpm;
  double end_time = 0.0;                      ///< time.end [s]
  bool fsi_zone = false;                      ///< the scene has zones.mpm
  std::optional<double> activation_pressure;  ///< [Pa], required with an FSI zone
  double handoff_radius = 0.0;                ///< [m], required with start = spherical
};

/// The burn state of one PARTICLES export (burn_fraction, material).
struct BurnObservation {
  std::size_t explosive_particles = 0;  ///< particles of an explosive material in it
  bool complete = false;                ///< handoff::detonation_complete over it
};

/// What the step just done showed; only the current phase's inputs are read.
struct Observation {
  double time = 0.0;  ///< t after the step [s]
  std::int64_t step = 0;
  std::optional<BurnObservation> charge_burn;   ///< mpm_detonation: charge_particles
  std::optional<BurnObservation> fluid_burn;    ///< mpm_detonation: fluid_particles, when asked for
  std::optional<bool> spherical_burn_complete;  ///< spherical_detonation: every F = 1
  std::optional<double> front_radius;           ///< spherical_detonation [m]
  std::vector<double> watch_pressure;           ///< fdm_blast with an FSI zone: fsi_watch [Pa]
};

/// A phase change: from, to, why, and the trigger's value against its threshold.
struct Transition {
  AfdmpPhase from = AfdmpPhase::done;
  AfdmpPhase to = AfdmpPhase::done;
  AfdmpTrigger trigger = AfdmpTrigger::end_time;
  double time = 0.0;
  std::int64_t step = 0;
  double value = 0.0;      ///< explosive particles, front radius [m], pressure [Pa], or t [s]
  double threshold = 0.0;  ///< -, handoff radius [m], activation pressure [Pa], or time.end [s]

  [[nodiscard]] nlohmann::json summary() const;
};

class PhaseMachine {
 public:
  /// Throws mpfd::Error for end_time <= 0, an FSI zone without activation
  /// pressure, or start = spherical without handoff_radius > 0.
  explicit PhaseMachine(const PhaseSettings& settings);

  [[nodiscard]] AfdmpPhase phase() const { return phase_; }
  /// mpm_detonation: the charge box lost explosive particles since the first
  /// observation; the step's check must come from the fluid_particles export.
  [[nodiscard]] bool needs_fluid_burn_check(const BurnObservation& charge_burn) const;
  /// Reads the current phase's inputs; returns the transition due now, if any
  /// (at most one per observation; the end time wins over a trigger). Throws
  /// mpfd::Error naming the phase and the missing input.
  std::optional<Transition> next(const Observation& observation);

  /// The phase, the charge's first explosive count and the FSI watch, in a coupled
  /// checkpoint (restart_file.hpp), and back.
  void save(RestartWriter& out) const;
  void restore(const RestartReader& in);

 private:
  std::optional<Transition> trigger(const Observation& observation);
  Transition move_to(AfdmpPhase to, AfdmpTrigger why, const Observation& observation, double value,
                     double threshold);

  PhaseSettings settings_;
  AfdmpPhase phase_;
  std::optional<std::size_t> explosive_at_start_;
  ActivationWatch watch_;
};

}  // namespace mpfd::coupler
