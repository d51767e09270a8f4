#pragma once
// Gauges of a coupled run (the thesis's tracking points, T §4.4.2 Fig. 4.11):
// each scene gauge is read by the solver whose zone owns its point — the MPM
// inside the MPM zone (nearest particle), the FDM elsewhere in the FDM zone
// (the cell holding it) — through the SampleGauges operation of protocol v1
// (proto/README.md §6), appended to the step's Exchange. The histories go to
// <out>/gauges.csv and gauges.h5 in the layout of the standalone solvers
// (docs/output.md), so the same plot tools read them. A scene with a material
// that has strength also records mises_stress [Pa], sampled by the MPM (0 in
// the FDM's fluid). A gauge with follow: material is the MPM's in every phase:
// the MPM reads the particle bound to it at Setup (mpm_solver/followed_gauges.hpp);
// while the MPM cannot be asked (a sleeping CFDMP zone, AFDMP's 1D stage) it
// records NaN. Each gauge's last columns are where it was read: the MPM's
// particle, or the gauge's own point for the FDM and the 1D stage.

#include <cstddef>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/io/gauge_recorder.hpp"
#include "cosim/message.hpp"
#include "coupler/run/restart_file.hpp"

namespace mpfd::coupler {

/// "mpm" for a point in the scene's MPM zone (bounds included) or a gauge that
/// follows the material, "fdm" for one elsewhere in the FDM zone. Throws
/// mpfd::Error naming the gauge when neither holds it. An AFDMP scene's fixed
/// gauges have no owner ("phase"): each phase's solver samples them all.
std::string gauge_owner(const config::Scene& scene, const config::Gauge& gauge);

/// Which solvers sample the gauges of a step.
enum class GaugeSamplers {
  owners,               ///< each gauge by the solver whose zone holds it (CFDMP, both awake)
  fdm_only,             ///< every fixed gauge by the FDM, the following ones by the idle MPM
                        ///< (AFDMP phase 2: the MPM holds the FSI zone's particles)
  fdm_only_mpm_asleep,  ///< every fixed gauge by the FDM, the following ones NaN
                        ///< (CFDMP while the MPM zone sleeps: it takes no Exchange)
  mpm_only,             ///< every gauge by the MPM (AFDMP phases 1 and 3)
};

class CoupledGauges {
 public:
  /// Opens <out_dir>/gauges.csv when the scene has gauges (a restarted run's in restore()).
  CoupledGauges(const config::Scene& scene, const std::filesystem::path& out_dir,
                io::GaugeStart start = io::GaugeStart::fresh);

  /// Appends SampleGauges to the requests of a step that ends at `time` [s] when a
  /// sample is due then (every step, or every output.gauge_interval); a request
  /// gets it only if its solver samples a gauge (`samplers`). `advance`: false for
  /// an exchange that does not move time (only the first one samples).
  void add(bool advance, double time, GaugeSamplers samplers, cosim::Message& fdm,
           cosim::Message& mpm);
  /// Records the sample asked for by the last add() from the replies (a solver
  /// that was asked nothing may pass an empty Message).
  void read(const cosim::Message& fdm, const cosim::Message& mpm);
  /// True when a sample is due at `time` (as add() decides); for a stage that
  /// samples without solvers (AFDMP's 1D spherical start).
  [[nodiscard]] bool due(double time) const;
  /// Records pressure [Pa] at every fixed gauge at `time` (the other quantities,
  /// and every quantity of a following gauge, NaN: a stage that knows only the
  /// fluid's pressure); call when due(time).
  void record_pressure(double time, std::span<const double> pressure);
  /// Writes gauges.h5 with every sample so far and flushes the CSV.
  void flush();

  /// Its state in a coupled checkpoint (restart_file.hpp): the schedule and every
  /// sample so far. restore() reads them; resume_files() then rewrites gauges.csv with
  /// them, last, once the restart can no longer be refused.
  void save(RestartWriter& out) const;
  void restore(const RestartReader& in);
  void resume_files();

  /// [{name, position [m], solver}] for summary.json.
  [[nodiscard]] nlohmann::json listing() const;
  [[nodiscard]] std::size_t sample_count() const {
    return recorder_ ? recorder_->sample_count() : 0;
  }

 private:
  struct Part {
    std::string peer;
    std::vector<std::size_t> gauges;  ///< indices into the scene's gauges
    std::vector<std::string> quantities;
    int operation = -1;  ///< index of SampleGauges in the pending request; -1: none
  };
  void add_to(Part& part, cosim::Message& request);
  void read_from(const Part& part, const cosim::Message& reply);
  void mark_unsampled_following();
  /// Gauge g's own point as its position columns (a gauge the FDM or the 1D stage reads).
  void record_fixed_position(std::size_t g);
  /// The first position column of a gauge.
  [[nodiscard]] std::size_t position_column() const;

  const config::Scene& scene_;
  std::optional<io::GaugeRecorder> recorder_;
  std::vector<std::string> owners_;
  Part fdm_, mpm_;
  Part fdm_all_;    ///< every fixed gauge, sampled by the FDM
  Part following_;  ///< every gauge that follows the material, sampled by the MPM
  Part mpm_all_;    ///< every gauge, sampled by the MPM
  void advance_schedule(double time);
  std::vector<double> values_;  ///< one quantity of a reply
  bool started_ = false;
  double next_sample_ = 0;
  double pending_time_ = 0;
  std::size_t quantities_ = 0;  ///< recorded per gauge: 8, or 9 with mises_stress
  /// gauge-major: density, pressure, velocity_x|y|z[, mises_stress], position_x|y|z
  std::vector<double> sample_;
  std::vector<double> restored_times_, restored_values_;  ///< restore() until resume_files()
};

}  // namespace mpfd::coupler
