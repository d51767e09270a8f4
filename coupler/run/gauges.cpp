#include "coupler/run/gauges.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <span>

#include "common/core/error.hpp"
#include "coupler/run/wire.hpp"

namespace mpfd::coupler {
namespace {

constexpr const char* kGroup = "gauges";
// density, pressure, velocity_x, velocity_y, velocity_z[, mises_stress], position_x, _y, _z
constexpr std::size_t kFluidQuantities = 5;
constexpr std::array<const char*, 3> kPositionNames = {"position_x", "position_y", "position_z"};

template <class Box>
bool holds(const Box& box, const config::Vec3& point) {
  for (int a = 0; a < 3; ++a)
    if (point[a] < box.lower[a] || point[a] > box.upper[a]) return false;
  return true;
}

}  // namespace

std::string gauge_owner(const config::Scene& scene, const config::Gauge& gauge) {
  // The scene check keeps a following gauge inside zones.mpm (scene_checks.cpp).
  if (gauge.follow == config::GaugeFollow::material) return "mpm";
  if (scene.solver.method == config::Method::afdmp) return "phase";
  if (scene.zones && scene.zones->mpm && holds(*scene.zones->mpm, gauge.position)) return "mpm";
  if (scene.zones && scene.zones->fdm && holds(*scene.zones->fdm, gauge.position)) return "fdm";
  throw Error("scene '" + scene.name + "': gauge '" + gauge.name + "' at (" +
              std::to_string(gauge.position[0]) + ", " + std::to_string(gauge.position[1]) + ", " +
              std::to_string(gauge.position[2]) +
              ") m lies in neither zones.fdm nor zones.mpm; a coupled run samples a gauge in the "
              "zone that owns it");
}

CoupledGauges::CoupledGauges(const config::Scene& scene, const std::filesystem::path& out_dir,
                             io::GaugeStart start)
    : scene_(scene) {
  // The names each solver's SampleGauges knows (fdm_solver/serve, mpm_solver/serve).
  fdm_ = {"fdm", {}, {"rho", "pressure", "velocity_x", "velocity_y", "velocity_z"}};
  mpm_ = {"mpm", {}, {"density", "pressure", "velocity_x", "velocity_y", "velocity_z"}};
  // A structure's stress (V5, T Figs. 3.12-3.14): the MPM samples it; an Euler
  // fluid has no deviatoric stress, so the FDM's samples keep 0.
  const bool structures = config::has_structure(scene);
  if (structures) mpm_.quantities.push_back("mises_stress");
  // Where the MPM read each gauge (its nearest or followed particle), as mpm_solver run's
  // gauges.csv; the FDM reads the cell holding the gauge's point, which is recorded.
  for (const char* name : kPositionNames) mpm_.quantities.push_back(name);
  quantities_ = (structures ? kFluidQuantities + 1 : kFluidQuantities) + kPositionNames.size();
  fdm_all_ = fdm_;
  mpm_all_ = mpm_;
  following_ = mpm_;
  std::vector<io::GaugePoint> points;
  for (std::size_t g = 0; g < scene.gauges.size(); ++g) {
    owners_.push_back(gauge_owner(scene, scene.gauges[g]));
    (owners_.back() == "mpm" ? mpm_ : fdm_).gauges.push_back(g);
    const bool follows = scene.gauges[g].follow == config::GaugeFollow::material;
    (follows ? following_ : fdm_all_).gauges.push_back(g);
    mpm_all_.gauges.push_back(g);
    points.push_back({scene.gauges[g].name, scene.gauges[g].position});
  }
  sample_.assign(quantities_ * points.size(), 0.0);
  if (points.empty()) return;
  const auto interval = scene.output.gauge_interval;
  // The quantities of `fdm_solver run`'s gauges.csv, so its plot tools apply.
  std::vector<io::GaugeQuantity> recorded{{"density", "kg/m^3"},
                                          {"pressure", "Pa"},
                                          {"velocity_x", "m/s"},
                                          {"velocity_y", "m/s"},
                                          {"velocity_z", "m/s"}};
  if (structures) recorded.push_back({"mises_stress", "Pa"});
  for (const char* name : kPositionNames) recorded.push_back({name, "m"});
  recorder_.emplace(out_dir, std::move(points), std::move(recorded), start);
  // Room for the samples up front, so recording does not allocate while stepping.
  if (interval)
    recorder_->reserve(static_cast<std::size_t>(
        std::min({scene.time.end / *interval + 16.0,
                  static_cast<double>(scene.time.max_steps) + 1.0, 1.0e7})));
}

void CoupledGauges::add_to(Part& part, cosim::Message& request) {
  part.operation = -1;
  if (part.gauges.empty()) return;
  part.operation = exchange_of(request).operations_size();
  auto& op = *next_operation(request, v1::Operation::kSample).mutable_sample();
  op.set_group(kGroup);
  for (const std::size_t g : part.gauges) {
    op.add_gauge_names(scene_.gauges[g].name);
    for (const double x : scene_.gauges[g].position) op.add_positions(x);
  }
  for (const auto& q : part.quantities) op.add_quantities(q);
}

bool CoupledGauges::due(double time) const {
  if (!recorder_) return false;
  const auto interval = scene_.output.gauge_interval;
  return !started_ || !interval || time >= next_sample_ * (1 - 1e-12);
}

void CoupledGauges::advance_schedule(double time) {
  started_ = true;
  // As the standalone loop (common/io/standalone_loop.hpp): the first step end at
  // or past each multiple of the interval.
  if (const auto interval = scene_.output.gauge_interval)
    while (next_sample_ <= time * (1 + 1e-12)) next_sample_ += *interval;
  pending_time_ = time;
}

void CoupledGauges::save(RestartWriter& out) const {
  out.number("gauges", "started", started_ ? 1 : 0);
  out.number("gauges", "next_sample", next_sample_);
  if (!recorder_) return;
  out.array("gauges", "times", recorder_->times());
  out.array("gauges", "values", recorder_->values());
}

void CoupledGauges::restore(const RestartReader& in) {
  started_ = in.number("gauges", "started") != 0;
  next_sample_ = in.number("gauges", "next_sample");
  if (!recorder_) return;
  restored_times_ = in.array("gauges", "times");
  restored_values_ = in.array("gauges", "values", restored_times_.size() * sample_.size());
}

void CoupledGauges::resume_files() {
  if (!recorder_) return;
  recorder_->resume(restored_times_, restored_values_);
  restored_times_ = {};
  restored_values_ = {};
}

void CoupledGauges::add(bool advance, double time, GaugeSamplers samplers, cosim::Message& fdm,
                        cosim::Message& mpm) {
  fdm_.operation = mpm_.operation = fdm_all_.operation = mpm_all_.operation = following_.operation =
      -1;
  if ((!advance && started_) || !due(time)) return;
  advance_schedule(time);
  switch (samplers) {
    case GaugeSamplers::owners:
      add_to(fdm_, fdm);
      add_to(mpm_, mpm);
      break;
    case GaugeSamplers::fdm_only:
      add_to(fdm_all_, fdm);
      add_to(following_, mpm);
      break;
    case GaugeSamplers::fdm_only_mpm_asleep:
      add_to(fdm_all_, fdm);
      break;
    case GaugeSamplers::mpm_only:
      add_to(mpm_all_, mpm);
      break;
  }
}

void CoupledGauges::record_pressure(double time, std::span<const double> pressure) {
  if (!due(time)) return;
  if (pressure.size() != scene_.gauges.size())
    throw Error("gauge pressures: " + std::to_string(pressure.size()) + " values for " +
                std::to_string(scene_.gauges.size()) + " gauges");
  advance_schedule(time);
  // The stage knows pressure only: the other quantities are not numbers, not zeros.
  std::fill(sample_.begin(), sample_.end(), std::numeric_limits<double>::quiet_NaN());
  for (const std::size_t g : fdm_all_.gauges) {
    sample_[quantities_ * g + 1] = pressure[g];
    record_fixed_position(g);
  }
  recorder_->record(time, sample_);
}

void CoupledGauges::read_from(const Part& part, const cosim::Message& reply) {
  if (part.operation < 0) return;
  const auto& result = result_of(reply, part.peer, part.operation);
  if (!result.has_sampled() || result.sampled().count() != part.gauges.size())
    throw Error("solver '" + part.peer + "' answered SampleGauges of " +
                std::to_string(part.gauges.size()) + " gauges with " +
                (result.has_sampled() ? std::to_string(result.sampled().count()) + " samples"
                                      : std::string("another result")));
  // What the part does not sample: the FDM's Mises stress is 0, its position the gauge's point.
  for (const std::size_t g : part.gauges) {
    for (std::size_t q = part.quantities.size(); q < position_column(); ++q)
      sample_[quantities_ * g + q] = 0.0;
    if (part.quantities.size() < quantities_) record_fixed_position(g);
  }
  for (std::size_t q = 0; q < part.quantities.size(); ++q) {
    read_doubles(reply, part.peer, kGroup, part.quantities[q], part.gauges.size(), values_);
    for (std::size_t i = 0; i < part.gauges.size(); ++i)
      sample_[quantities_ * part.gauges[i] + q] = values_[i];
  }
}

std::size_t CoupledGauges::position_column() const {
  return quantities_ - kPositionNames.size();
}

void CoupledGauges::record_fixed_position(std::size_t g) {
  for (std::size_t a = 0; a < kPositionNames.size(); ++a)
    sample_[quantities_ * g + position_column() + a] = scene_.gauges[g].position[a];
}

void CoupledGauges::mark_unsampled_following() {
  if (following_.operation >= 0 || mpm_.operation >= 0 || mpm_all_.operation >= 0) return;
  for (const std::size_t g : following_.gauges)
    std::fill_n(sample_.begin() + static_cast<std::ptrdiff_t>(quantities_ * g), quantities_,
                std::numeric_limits<double>::quiet_NaN());
}

void CoupledGauges::read(const cosim::Message& fdm, const cosim::Message& mpm) {
  if (fdm_.operation < 0 && mpm_.operation < 0 && fdm_all_.operation < 0 &&
      mpm_all_.operation < 0 && following_.operation < 0)
    return;
  mark_unsampled_following();
  read_from(fdm_all_, fdm);
  read_from(following_, mpm);
  read_from(mpm_all_, mpm);
  read_from(fdm_, fdm);
  read_from(mpm_, mpm);
  recorder_->record(pending_time_, sample_);
  fdm_.operation = mpm_.operation = fdm_all_.operation = mpm_all_.operation = following_.operation =
      -1;
}

void CoupledGauges::flush() {
  if (recorder_) recorder_->flush();
}

nlohmann::json CoupledGauges::listing() const {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t g = 0; g < scene_.gauges.size(); ++g)
    list.push_back(
        {{"name", scene_.gauges[g].name},
         {"position", scene_.gauges[g].position},
         {"solver", owners_[g]},
         {"follow",
          scene_.gauges[g].follow == config::GaugeFollow::material ? "material" : "point"}});
  return list;
}

}  // namespace mpfd::coupler
