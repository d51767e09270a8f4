#include "mpm_solver/standalone_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/io/gauge_recorder.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/run_summary.hpp"
#include "common/io/snapshot_writer.hpp"
#include "common/io/standalone_loop.hpp"
#include "mpm_solver/cell_fields.hpp"
#include "mpm_solver/followed_gauges.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "mpm_solver/snapshot_particles.hpp"

namespace mpfd::mpm {
namespace {

using Clock = std::chrono::steady_clock;

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
  CellFields cell_fields(scene, solver.grid());
  std::vector<io::GaugePoint> points;
  for (const auto& g : scene.gauges) points.push_back({g.name, g.position});
  io::GaugeRecorder gauges(options.out_dir, points,
                           {{"density", "kg/m^3"},
                            {"pressure", "Pa"},
                            {"velocity_x", "m/s"},
                            {"velocity_y", "m/s"},
                            {"velocity_z", "m/s"},
                            {"position_x", "m"},
                            {"position_y", "m"},
                            {"position_z", "m"},
                            {"cell_density", "kg/m^3"},
                            {"cell_pressure", "Pa"},
                            {"cell_velocity_x", "m/s"},
                            {"cell_velocity_y", "m/s"},
                            {"cell_velocity_z", "m/s"}});
  // Room for the samples up front, so recording does not allocate while stepping.
  const double per_step = scene.time.end / solver.stable_dt();
  const double interval_samples =
      scene.output.gauge_interval ? scene.time.end / *scene.output.gauge_interval : per_step;
  if (!points.empty())
    gauges.reserve(static_cast<std::size_t>(
        std::min({2.0 * std::min(interval_samples, per_step) + 16.0,
                  static_cast<double>(scene.time.max_steps) + 1.0, 1.0e7})));
  std::vector<grid::Vec3> gauge_positions;
  for (const auto& g : points) gauge_positions.push_back(g.position);
  GaugeCells gauge_cells(solver.grid(), gauge_positions);
  // Gauges with follow: material are bound now, at t = 0, to their particles.
  FollowedGauges followed(scene.gauges, solver.particles(), binding_reach(solver.grid()));
  constexpr std::size_t kParticleValues = 8, kValues = kParticleValues + 5;
  std::vector<double> cell_sample(5 * points.size());
  std::vector<double> sample(kValues * points.size());
  const auto record_gauges = [&] {
    const ParticleSet& ps = solver.particles();
    if (ps.size() == 0) return;
    for (std::size_t g = 0; g < points.size(); ++g) {
      const std::size_t p = followed.follows(points[g].name)
                                ? followed.particle(points[g].name, ps)
                                : nearest_particle(ps, points[g].position);
      const auto at = sample.begin() + static_cast<std::ptrdiff_t>(kValues * g);
      if (p == FollowedGauges::kLeft) {
        std::fill_n(at, kParticleValues, std::numeric_limits<double>::quiet_NaN());
        continue;
      }
      const double values[kParticleValues] = {
          ps.density[p],     ps.pressure[p],    ps.velocity[0][p], ps.velocity[1][p],
          ps.velocity[2][p], ps.position[0][p], ps.position[1][p], ps.position[2][p]};
      std::copy(values, values + kParticleValues, at);
    }
    gauge_cells.sample(ps, cell_sample);
    for (std::size_t g = 0; g < points.size(); ++g)
      std::copy_n(cell_sample.begin() + static_cast<std::ptrdiff_t>(5 * g), 5,
                  sample.begin() + static_cast<std::ptrdiff_t>(kValues * g + kParticleValues));
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
    // Plastic work is part of the internal energy (it heats); shown apart for metals.
    const ParticleSet& ps = solver.particles();
    double plastic_work = 0.0;
    for (std::size_t p = 0; p < ps.size(); ++p) plastic_work += ps.mass[p] * ps.plastic_work[p];
    summary.set_detail("energy_J", {{"kinetic", now.kinetic_energy},
                                    {"internal", now.internal_energy},
                                    {"plastic_work_in_internal", plastic_work},
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
    summary.set_detail("update", update_name(solver.settings().update));
    summary.set_detail("peak_memory_bytes", io::peak_memory_bytes());
    summary.set_detail("solver_time_s", solver_seconds);
    summary.set_detail("particle_updates", solver.particle_updates());
    summary.set_status(status, error);
    summary.write(options.out_dir / "summary.json");
  };
  const auto write_output = [&] {
    snapshots.write(solver.steps(), solver.time(), cell_fields.views(solver),
                    particle_fields.views(solver));
    gauges.flush();
    write_summary("running", "");
  };

  io::StandaloneCallbacks callbacks;
  callbacks.has_gauges = !points.empty();
  callbacks.record_gauges = record_gauges;
  callbacks.write_output = write_output;
  callbacks.flush_gauges = [&] { gauges.flush(); };
  callbacks.write_summary = write_summary;
  io::run_standalone_loop(solver, scene, "mpm_solver", "mpm", callbacks, solver_seconds);
  logger.info("'", scene.name, "' done: ", solver.steps(), " steps to t = ", solver.time(), " s, ",
              solver.particle_updates() / std::max(solver_seconds, 1e-12) / 1e6,
              " M particle-updates/s; output in ", options.out_dir.string());
}

}  // namespace mpfd::mpm
