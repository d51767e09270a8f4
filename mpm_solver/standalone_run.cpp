#include "mpm_solver/standalone_run.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/core/progress.hpp"
#include "common/io/gauge_recorder.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/run_summary.hpp"
#include "common/io/snapshot_writer.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "mpm_solver/snapshot_particles.hpp"

namespace mpfd::mpm {
namespace {

using Clock = std::chrono::steady_clock;

/// Peak resident memory of this process so far [bytes].
long long peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024LL * usage.ru_maxrss;  // Linux reports kilobytes
}

}  // namespace

void run_standalone(const config::Scene& scene, const RunOptions& options) {
  const Logger logger("mpm.run");
  if (scene.solver.method != config::Method::mpm)
    throw Error("scene '" + scene.name +
                "': mpm_solver runs scenes with solver.method: mpm; this one asks for another "
                "method");
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  io::prepare_output_directory(options.out_dir, options.overwrite);

  io::RunSummary summary("mpm_solver run", scene.name, options.scene_file);
  io::SnapshotWriter snapshots(options.out_dir, solver.grid());
  SnapshotParticles particle_fields;
  std::vector<io::GaugePoint> points;
  for (const auto& g : scene.gauges) points.push_back({g.name, g.position});
  io::GaugeRecorder gauges(options.out_dir, points,
                           {{"density", "kg/m^3"},
                            {"pressure", "Pa"},
                            {"velocity_x", "m/s"},
                            {"velocity_y", "m/s"},
                            {"velocity_z", "m/s"}});
  // Room for the samples up front, so recording does not allocate while stepping.
  const double per_step = scene.time.end / solver.stable_dt();
  const double interval_samples =
      scene.output.gauge_interval ? scene.time.end / *scene.output.gauge_interval : per_step;
  if (!points.empty())
    gauges.reserve(static_cast<std::size_t>(
        std::min({2.0 * std::min(interval_samples, per_step) + 16.0,
                  static_cast<double>(scene.time.max_steps) + 1.0, 1.0e7})));
  std::vector<double> sample(5 * points.size());
  const auto record_gauges = [&] {
    const ParticleSet& ps = solver.particles();
    if (ps.size() == 0) return;
    for (std::size_t g = 0; g < points.size(); ++g) {
      const std::size_t p = nearest_particle(ps, points[g].position);
      const double values[5] = {ps.density[p], ps.pressure[p], ps.velocity[0][p], ps.velocity[1][p],
                                ps.velocity[2][p]};
      std::copy(values, values + 5, sample.begin() + static_cast<std::ptrdiff_t>(5 * g));
    }
    gauges.record(solver.time(), sample);
  };

  const MpmTotals initial = solver.totals();
  const double initial_energy = initial.kinetic_energy + initial.internal_energy;
  const double momentum_scale = std::sqrt(2.0 * initial.mass * std::abs(initial_energy));
  const auto start = Clock::now();
  double solver_seconds = 0.0;
  const auto write_summary = [&](const std::string& status, const std::string& error) {
    const MpmTotals now = solver.totals();
    const BoundaryLedger& ledger = solver.boundary_ledger();
    std::vector<io::ConservationEntry> audit = {
        {"mass", "kg", initial.mass, now.mass, ledger.mass},
        {"energy", "J", initial_energy, now.kinetic_energy + now.internal_energy, ledger.energy}};
    const char* axis[3] = {"momentum_x", "momentum_y", "momentum_z"};
    for (int a = 0; a < 3; ++a)
      audit.push_back(
          {axis[a], "kg m/s", initial.momentum[a], now.momentum[a], ledger.momentum[a]});
    summary.set_conservation(audit, momentum_scale);
    summary.set_detail("audit_scale",
                       {{"value", momentum_scale},
                        {"meaning", "sqrt(2 M E): momentum errors are relative to it"}});
    summary.set_detail("energy_J", {{"kinetic", now.kinetic_energy},
                                    {"internal", now.internal_energy},
                                    {"boundary_outflow", ledger.energy}});
    summary.set_detail("momentum_boundary",
                       "momentum boundary_outflow = carried out by removed particles minus the "
                       "impulse fixed and symmetry faces gave");
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    summary.set_progress(solver.steps(), solver.time(), scene.time.end, wall);
    summary.set_rate("particle_updates_per_second",
                     solver_seconds > 0 ? solver.particle_updates() / solver_seconds : 0.0);
    summary.set_detail("particles", solver.particles().size());
    summary.set_detail("particles_removed", ledger.particles_removed);
    summary.set_detail("grid_nodes_allocated", solver.sparse_grid().node_count());
    summary.set_detail("shape_function", shape_function_name(solver.settings().shape_function));
    summary.set_detail("update",
                       solver.settings().update == config::MpmUpdate::musl ? "musl" : "usl");
    summary.set_detail("peak_memory_bytes", peak_memory_bytes());
    summary.set_detail("solver_time_s", solver_seconds);
    summary.set_detail("particle_updates", solver.particle_updates());
    summary.set_status(status, error);
    summary.write(options.out_dir / "summary.json");
  };
  const auto write_output = [&] {
    snapshots.write(solver.steps(), solver.time(), {}, particle_fields.views(solver));
    gauges.flush();
    write_summary("running", "");
  };

  try {
    ProgressLine progress(std::cerr, scene.time.end, "mpm");
    const double end = scene.time.end;
    double next_output = 0.0;
    double next_gauge = 0.0;
    while (true) {
      if (!points.empty() && (!scene.output.gauge_interval || solver.time() >= next_gauge)) {
        record_gauges();
        if (scene.output.gauge_interval)
          while (next_gauge <= solver.time()) next_gauge += *scene.output.gauge_interval;
      }
      if (solver.time() >= next_output || solver.time() >= end) {
        write_output();
        while (next_output <= solver.time()) next_output += scene.output.interval;
      }
      if (solver.time() >= end) break;
      if (solver.steps() >= scene.time.max_steps)
        throw Error("mpm_solver: reached time.max_steps = " + std::to_string(scene.time.max_steps) +
                    " at t = " + std::to_string(solver.time()) + " s of " + std::to_string(end) +
                    " s; raise time.max_steps or coarsen the grid");
      const double dt = solver.step_toward(std::min(next_output, end));  // land on output times
      const auto step_start = Clock::now();
      solver.advance(dt);
      solver_seconds += std::chrono::duration<double>(Clock::now() - step_start).count();
      progress.update(solver.steps(), solver.time());
    }
    progress.finish(solver.steps(), solver.time());
    write_summary("completed", "");
  } catch (const std::exception& e) {
    // Keep what was recorded, but never let a second failure hide the first.
    try {
      gauges.flush();
      write_summary("failed", e.what());
    } catch (const std::exception&) {
    }
    throw;
  }
  logger.info("'", scene.name, "' done: ", solver.steps(), " steps to t = ", solver.time(), " s, ",
              solver.particle_updates() / std::max(solver_seconds, 1e-12) / 1e6,
              " M particle-updates/s; output in ", options.out_dir.string());
}

}  // namespace mpfd::mpm
