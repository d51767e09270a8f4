#pragma once
// The dormant FSI zone (T §4.3, scene key zones.mpm.activation_pressure). T
// starts the FSI zone asleep "to save computation" and wakes it "when the
// cell-centre pressure at the interface of the two zones (the dashed line of
// Fig. 4.1) reaches the preset threshold" (T §4.3, also §3.1 for AFDMP). The
// cells at that interface are the coupler's strip_cells (cells k-w and k-w+1
// on both sides of the MPM zone's face, proto §6), whose pressure the FDM
// exports every step anyway, so the watch costs no extra message. The
// threshold is an absolute pressure, as in T (the thesis compares the cell
// pressure itself; scene value in Pa): a threshold at or below the ambient
// pressure on the strip wakes the zone at t = 0.
//
// While dormant the MPM gets no request after Setup, only a keep-alive Ping a
// second (Zone.dormant, proto §5); the FDM advances alone over the scene's whole
// grid with its own dt. The zone wakes at the start of the step after the one whose strip export
// passed the threshold: Activate, then the step-0 exchange (discard, export, propose).
//
// Audit: while the zone sleeps it counts the FDM's cells of the FDM zone and of the
// MPM zone (the whole domain when the zones cover it), so it is exact as long as
// the FDM alone conserves. At the switch the MPM's particles (the scene's initial
// state) replace the FDM's cells of the zone; the difference, what the FDM carried
// across the face before the switch, goes to summary.json (activation.audit_switch)
// and the log, and is kept out of the audit's error, which stays continuous.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "coupler/run/restart_file.hpp"

namespace mpfd::coupler {

class ActivationWatch {
 public:
  /// `threshold` [Pa]: zones.mpm.activation_pressure; absent: active from the start.
  explicit ActivationWatch(std::optional<double> threshold);

  /// The MPM zone sleeps (no request to the MPM solver).
  [[nodiscard]] bool dormant() const { return dormant_; }
  /// Reads the FDM's strip_cells pressure at `time` [s] while dormant.
  void observe(const std::vector<double>& strip_pressure, double time);
  /// The threshold was passed and the zone is still asleep: wake it now.
  [[nodiscard]] bool due() const { return dormant_ && trigger_time_.has_value(); }
  /// The zone woke at the start of step `step` + 1, at `time` [s].
  void activated(double time, std::int64_t step);

  /// For summary.json: the threshold, whether and when the zone woke, and what woke it.
  [[nodiscard]] nlohmann::json summary() const;
  /// The one log line of the switch.
  [[nodiscard]] std::string activation_text() const;

  /// Its state in a coupled checkpoint (restart_file.hpp), and back.
  void save(RestartWriter& out) const;
  void restore(const RestartReader& in);

 private:
  std::optional<double> threshold_;
  bool dormant_ = false;
  std::optional<double> trigger_time_;  ///< when the strip pressure passed the threshold [s]
  double trigger_pressure_ = 0;         ///< the largest strip pressure then [Pa]
  double peak_pressure_ = 0;            ///< the largest strip pressure seen while dormant [Pa]
  std::optional<double> activation_time_;
  std::int64_t activation_step_ = 0;
};

}  // namespace mpfd::coupler
