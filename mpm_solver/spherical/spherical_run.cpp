#include "mpm_solver/spherical/spherical_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/io/gauge_recorder.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/run_summary.hpp"
#include "common/io/standalone_loop.hpp"
#include "mpm_solver/spherical/scene_layers.hpp"
#include "mpm_solver/spherical/spherical_mpm.hpp"

namespace mpfd::mpm::spherical {
namespace {

using Clock = std::chrono::steady_clock;

/// SphericalMpm with the step count and step_toward() of io::run_standalone_loop.
class SteppedSphere {
 public:
  explicit SteppedSphere(SphericalMpm& mpm) : mpm_(mpm) {}
  [[nodiscard]] double time() const { return mpm_.time(); }
  [[nodiscard]] std::int64_t steps() const { return steps_; }
  /// The stable step, shortened to land on `target`.
  [[nodiscard]] double step_toward(double target) const {
    return std::min(mpm_.stable_dt(), target - mpm_.time());
  }
  void advance(double dt) {
    mpm_.advance(dt);
    ++steps_;
  }

 private:
  SphericalMpm& mpm_;
  std::int64_t steps_ = 0;
};

// %.17g: a profile read back gives the particle values bit for bit.
void write_profile(std::ostream& out, const RadialProfile& p) {
  out << "radius[m],mass_per_steradian[kg/sr],velocity[m/s],density[kg/m^3],pressure[Pa],"
         "specific_internal_energy[J/kg],stress_rr[Pa],stress_hoop[Pa],burn_fraction[-],layer\n";
  char line[512];
  for (std::size_t i = 0; i < p.radius.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d\n",
                  p.radius[i], p.mass_per_steradian[i], p.velocity[i], p.density[i], p.pressure[i],
                  p.specific_internal_energy[i], p.stress_rr[i], p.stress_hoop[i],
                  p.burn_fraction[i], p.layer[i]);
    out << line;
  }
}

}  // namespace

void run_spherical(const config::Scene& scene, const SphericalRunOptions& options) {
  const Logger logger("mpm.spherical");
  if (scene.domain.geometry != config::Geometry::spherical)
    throw Error("scene '" + scene.name +
                "': the 1D spherical run needs domain.geometry: spherical");
  SphericalMpm mpm(layers_from_scene(scene), options_from_scene(scene));
  SteppedSphere stepper(mpm);
  io::prepare_output_directory(options.out_dir, options.overwrite);
  const std::filesystem::path profiles = options.out_dir / "profiles";
  std::filesystem::create_directories(profiles);
  std::ofstream times(profiles / "times.csv");
  times << "index,step,time[s]\n";

  io::RunSummary summary("mpm_solver run", scene.name, options.scene_file);
  std::vector<io::GaugePoint> points;
  std::vector<double> radii;
  for (const auto& g : scene.gauges) {
    points.push_back({g.name, g.position});
    radii.push_back(g.position[0]);  // x is the radius
  }
  io::GaugeRecorder gauges(options.out_dir, points, {{"pressure", "Pa"}});
  // Room for every sample up front, so recording does not allocate while stepping.
  if (!points.empty()) {
    const double per_step = 2.0 * scene.time.end / mpm.stable_dt() + 16.0;
    const double samples =
        scene.output.gauge_interval
            ? std::min(per_step, scene.time.end / *scene.output.gauge_interval + 16.0)
            : per_step;
    gauges.reserve(static_cast<std::size_t>(
        std::min({samples, static_cast<double>(scene.time.max_steps) + 1.0, 1.0e7})));
  }
  std::vector<double> sample(points.size());
  const auto record_gauges = [&] {
    for (std::size_t g = 0; g < radii.size(); ++g) sample[g] = mpm.pressure_at(radii[g]);
    gauges.record(mpm.time(), sample);
  };

  const SphericalTotals initial = mpm.totals();
  const double initial_energy = initial.kinetic_energy + initial.internal_energy;
  const auto start = Clock::now();
  double solver_seconds = 0.0;
  RadialProfile profile;
  int output_index = 0;
  const auto write_summary = [&](const std::string& status, const std::string& error) {
    const SphericalTotals now = mpm.totals();
    // The 1D line keeps every particle (the outer surface moves): no mass leaves.
    summary.set_conservation(
        {{"mass", "kg", initial.mass, now.mass, 0.0},
         {"energy", "J", initial_energy, now.kinetic_energy + now.internal_energy, 0.0}});
    summary.set_detail("audit_note",
                       "boundary_outflow is 0: the work of a transmitting outer surface is not "
                       "booked, so the energy audit holds until the wave reaches it");
    summary.set_detail("energy_J",
                       {{"kinetic", now.kinetic_energy}, {"internal", now.internal_energy}});
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    summary.set_progress(stepper.steps(), mpm.time(), scene.time.end, wall);
    const double updates =
        static_cast<double>(stepper.steps()) * static_cast<double>(mpm.particles().size());
    summary.set_rate("particle_updates_per_second",
                     solver_seconds > 0 ? updates / solver_seconds : 0.0);
    summary.set_detail("geometry", "spherical");
    summary.set_detail("particles", mpm.particles().size());
    summary.set_detail("grid_spacing_m", mpm.options().grid_spacing);
    summary.set_detail("shape_function",
                       mpm.options().shape == RadialShape::gimp ? "gimp" : "linear");
    summary.set_detail("outer_boundary", mpm.options().outer_boundary == OuterBoundary::free
                                             ? "free"
                                             : "transmitting");
    summary.set_detail("peak_memory_bytes", io::peak_memory_bytes());
    summary.set_detail("solver_time_s", solver_seconds);
    summary.set_status(status, error);
    summary.write(options.out_dir / "summary.json");
  };
  const auto write_output = [&] {
    char name[32];
    std::snprintf(name, sizeof name, "profile_%06d.csv", output_index);
    mpm.export_profile(profile);
    io::write_file_atomically(profiles / name,
                              [&](std::ostream& out) { write_profile(out, profile); });
    char line[96];
    std::snprintf(line, sizeof line, "%d,%lld,%.17g\n", output_index,
                  static_cast<long long>(stepper.steps()), mpm.time());
    times << line << std::flush;
    ++output_index;
    gauges.flush();
    write_summary("running", "");
  };

  io::StandaloneCallbacks callbacks;
  callbacks.has_gauges = !points.empty();
  callbacks.record_gauges = record_gauges;
  callbacks.write_output = write_output;
  callbacks.flush_gauges = [&] { gauges.flush(); };
  callbacks.write_summary = write_summary;
  io::run_standalone_loop(stepper, scene, "mpm_solver", "mpm 1D", callbacks, solver_seconds);
  logger.info("'", scene.name, "' done: ", stepper.steps(), " steps to t = ", mpm.time(),
              " s on the 1D spherical line; output in ", options.out_dir.string());
}

}  // namespace mpfd::mpm::spherical
