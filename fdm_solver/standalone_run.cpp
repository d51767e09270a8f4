#include "fdm_solver/standalone_run.hpp"

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
#include "fdm_solver/cell_eos.hpp"
#include "fdm_solver/primitive_fields.hpp"
#include "fdm_solver/snapshot_fields.hpp"
#include "fdm_solver/sweep_kernel.hpp"

namespace mpfd::fdm {
namespace {

using Clock = std::chrono::steady_clock;

constexpr const char* kAuditName[kVariables] = {"mass", "momentum_x", "momentum_y", "momentum_z",
                                                "energy"};
constexpr const char* kAuditUnits[kVariables] = {"kg", "kg m/s", "kg m/s", "kg m/s", "J"};

}  // namespace

void run_standalone(const config::Scene& scene, const RunOptions& options) {
  const Logger logger("fdm.run");
  auto solver_options = SolverOptions::from_scene(scene);
  solver_options.skip_quiet = options.skip_quiet;
  EulerSolver solver(scene, solver_options);
  PrimitiveFields primitives;
  primitives.compute(solver.state(), solver.materials());
  std::vector<std::string> field_names;
  for (const auto f : scene.output.fields) field_names.push_back(field_name(f));
  const SnapshotFields fields(solver, field_names);  // checks them before anything is written
  io::prepare_output_directory(options.out_dir, options.overwrite);

  const auto& grid = solver.state().grid;
  io::RunSummary summary("fdm_solver run", scene.name, options.scene_file);
  io::SnapshotWriter snapshots(options.out_dir, grid);
  std::vector<io::GaugePoint> points;
  std::vector<std::size_t> gauge_cells;
  for (const auto& g : scene.gauges) {
    points.push_back({g.name, g.position});
    const auto where = grid.locate(g.position);
    if (!where)
      throw Error("scene '" + scene.name + "': gauge '" + g.name + "' is outside the grid");
    gauge_cells.push_back(grid.cell_index(where->cell));
  }
  io::GaugeRecorder gauges(options.out_dir, points,
                           {{"density", "kg/m^3"},
                            {"pressure", "Pa"},
                            {"velocity_x", "m/s"},
                            {"velocity_y", "m/s"},
                            {"velocity_z", "m/s"}});
  // Room for the samples up front, so recording does not allocate while
  // stepping: one per gauge interval, or per step, estimated from the first
  // stable step (twice that, for steps that shrink as the flow speeds up).
  const double per_step = scene.time.end / solver.stable_dt();
  const double interval_samples =
      scene.output.gauge_interval ? scene.time.end / *scene.output.gauge_interval : per_step;
  if (!gauge_cells.empty())
    gauges.reserve(static_cast<std::size_t>(
        std::min({2.0 * std::min(interval_samples, per_step) + 16.0,
                  static_cast<double>(scene.time.max_steps) + 1.0, 1.0e7})));
  std::vector<double> sample(5 * gauge_cells.size());
  const auto record_gauges = [&] {
    // Gauges read the cell that holds them; only their cells need primitives.
    const auto& u = solver.state().u;
    for (std::size_t g = 0; g < gauge_cells.size(); ++g) {
      const std::size_t c = gauge_cells[g];
      const double rho = u[kDensity][c];
      const double v[3] = {u[kMomentumX][c] / rho, u[kMomentumY][c] / rho, u[kMomentumZ][c] / rho};
      const double e = u[kEnergy][c] / rho - 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      const double p = cell_pressure(solver.state(), solver.materials(), c, rho, e);
      const double values[5] = {rho, p, v[0], v[1], v[2]};
      std::copy(values, values + 5, sample.begin() + static_cast<std::ptrdiff_t>(5 * g));
    }
    gauges.record(solver.time(), sample);
  };

  const Totals initial = solver.totals();
  const double momentum_scale = std::sqrt(2.0 * initial[kDensity] * initial[kEnergy]);
  const auto start = Clock::now();
  double solver_seconds = 0.0;
  const auto write_summary = [&](const std::string& status, const std::string& error) {
    const Totals now = solver.totals();
    std::vector<io::ConservationEntry> audit;
    for (std::size_t v = 0; v < kVariables; ++v)
      audit.push_back({kAuditName[v], kAuditUnits[v], initial[v], now[v], solver.outflow()[v]});
    summary.set_conservation(audit, momentum_scale);
    summary.set_detail("audit_scale",
                       {{"value", momentum_scale},
                        {"meaning", "sqrt(2 M E): momentum errors are relative to it"}});
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    summary.set_progress(solver.steps(), solver.time(), scene.time.end, wall);
    summary.set_rate("cell_updates_per_second",
                     solver_seconds > 0 ? solver.cell_updates() / solver_seconds : 0.0);
    summary.set_detail("cells", grid.cell_count());
    summary.set_detail("peak_memory_bytes", io::peak_memory_bytes());
    summary.set_detail("peak_memory_bytes_per_cell", static_cast<double>(io::peak_memory_bytes()) /
                                                         static_cast<double>(grid.cell_count()));
    summary.set_detail("solver_time_s", solver_seconds);
    summary.set_detail("sweep_kernel", sweep_kernel_name());
    summary.set_detail("cell_updates", solver.cell_updates());
    summary.set_status(status, error);
    summary.write(options.out_dir / "summary.json");
  };
  std::vector<double> tracer_material;  // tracers' material index as numbers, for output
  const auto write_output = [&] {
    primitives.compute(solver.state(), solver.materials());
    std::vector<io::FieldView> tracer_fields;
    if (const auto* tracker = solver.tracker()) {  // the tracers, as particles (docs/output.md)
      const TracerSet& t = tracker->tracers();
      tracer_material.assign(t.material.begin(), t.material.end());
      tracer_fields = {{"position", "m", {t.position[0], t.position[1], t.position[2]}},
                       {"material", "", {tracer_material}},
                       {"volume", "m^3", {t.volume}}};
    }
    snapshots.write(solver.steps(), solver.time(),
                    fields.views(field_names, scene, solver, primitives), tracer_fields);
    gauges.flush();
    write_summary("running", "");
  };

  io::StandaloneCallbacks callbacks;
  callbacks.has_gauges = !gauge_cells.empty();
  callbacks.record_gauges = record_gauges;
  callbacks.write_output = write_output;
  callbacks.flush_gauges = [&] { gauges.flush(); };
  callbacks.write_summary = write_summary;
  io::run_standalone_loop(solver, scene, "fdm_solver", "fdm", callbacks, solver_seconds);
  logger.info("'", scene.name, "' done: ", solver.steps(), " steps to t = ", solver.time(), " s, ",
              solver.cell_updates() / std::max(solver_seconds, 1e-12) / 1e6,
              " M cell-updates/s; output in ", options.out_dir.string());
}

}  // namespace mpfd::fdm
