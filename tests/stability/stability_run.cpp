#include "tests/stability/stability_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "common/io/hdf5_file.hpp"
#include "coupler/run/launch.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/primitive_fields.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::stability {
namespace {

Samples fdm_samples(const fdm::EulerSolver& solver) {
  fdm::PrimitiveFields f;
  f.compute(solver.state(), solver.materials());
  const auto& g = solver.state().grid;
  Samples s;
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    const auto centre = g.cell_center(g.cell_of_index(c));
    s.x.push_back(centre[0]);
    s.y.push_back(centre[1]);
    s.density.push_back(solver.state().u[fdm::kDensity][c]);
    s.speed.push_back(std::hypot(f.velocity_x[c], f.velocity_y[c], f.velocity_z[c]));
    s.pressure.push_back(f.pressure[c]);
    s.volume.push_back(g.cell_volume());
  }
  return s;
}

Samples mpm_samples(const mpm::MpmSolver& solver) {
  const auto& ps = solver.particles();
  Samples s;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    s.x.push_back(ps.position[0][p]);
    s.y.push_back(ps.position[1][p]);
    s.density.push_back(ps.density[p]);
    s.speed.push_back(std::hypot(ps.velocity[0][p], ps.velocity[1][p], ps.velocity[2][p]));
    s.pressure.push_back(ps.pressure[p]);
    s.volume.push_back(ps.mass[p] / ps.density[p]);
  }
  return s;
}

std::filesystem::path snapshot_file(const std::filesystem::path& out, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "snapshot_%06d.h5", index);
  return out / "snapshots" / name;
}

/// A coupled snapshot: the FDM cells below the MPM zone's lower x, the
/// particles above it (the cells beyond are not the FDM's to report).
Samples cfdmp_samples(const std::filesystem::path& out, int index, const config::Scene& scene) {
  const io::Hdf5File h5(snapshot_file(out / "fdm", index), io::Hdf5File::Mode::read);
  const io::Hdf5File particles(snapshot_file(out / "mpm", index), io::Hdf5File::Mode::read);
  const double face = scene.zones->mpm->lower[0];
  const auto g =
      grid::UniformGrid::from_bounds(scene.domain.lower, scene.domain.upper, scene.domain.cells);
  Samples s;
  {
    const auto rho = h5.read_dataset("/cells/density").values;
    const auto u = h5.read_dataset("/cells/velocity").values;
    const auto p = h5.read_dataset("/cells/pressure").values;
    for (std::size_t c = 0; c < rho.size(); ++c) {
      const auto centre = g.cell_center(g.cell_of_index(c));
      if (centre[0] >= face) continue;
      s.x.push_back(centre[0]);
      s.y.push_back(centre[1]);
      s.density.push_back(rho[c]);
      s.speed.push_back(std::hypot(u[3 * c], u[3 * c + 1], u[3 * c + 2]));
      s.pressure.push_back(p[c]);
      s.volume.push_back(g.cell_volume());
    }
  }
  const auto x = particles.read_dataset("/particles/position").values;
  const auto rho = particles.read_dataset("/particles/density").values;
  const auto u = particles.read_dataset("/particles/velocity").values;
  const auto p = particles.read_dataset("/particles/pressure").values;
  const auto m = particles.read_dataset("/particles/mass").values;
  for (std::size_t i = 0; i < rho.size(); ++i) {
    if (x[3 * i] < face) continue;
    s.x.push_back(x[3 * i]);
    s.y.push_back(x[3 * i + 1]);
    s.density.push_back(rho[i]);
    s.speed.push_back(std::hypot(u[3 * i], u[3 * i + 1], u[3 * i + 2]));
    s.pressure.push_back(p[i]);
    s.volume.push_back(m[i] / rho[i]);
  }
  return s;
}

Outcome run_cfdmp(const std::string& text, const std::filesystem::path& work) {
  std::filesystem::remove_all(work);
  std::filesystem::create_directories(work);
  const auto scene_file = work / "scene.yaml";
  std::ofstream(scene_file) << text;
  const auto out = work / "out";
  coupler::CoupledRunOptions options;
  options.out_dir = out;
  options.progress = false;
  Outcome o;
  const auto scene = config::load_scene(scene_file);
  try {
    o.steps = coupler::launch_run(scene_file, coupler::LaunchOptions{}, options, "").steps;
  } catch (const Error& e) {
    o.stopped = true;
    o.message = e.what();
  }
  const auto written = [&](int index) {
    return std::filesystem::exists(snapshot_file(out / "fdm", index)) &&
           std::filesystem::exists(snapshot_file(out / "mpm", index));
  };
  if (written(1)) o.half = cfdmp_samples(out, 1, scene);
  if (!o.stopped && written(2)) o.end = cfdmp_samples(out, 2, scene);
  return o;
}

/// A run whose step collapses takes forever: this many steps end it, unstopped.
constexpr std::int64_t kStepCap = 200000;

template <class Solver, class Sampler>
Outcome run_solver(Solver& solver, double end, const Sampler& sample) {
  Outcome o;
  const auto advance_to = [&](double target) {
    while (solver.time() < target && solver.steps() < kStepCap)
      solver.advance(solver.step_toward(target));
    return solver.time() >= target;
  };
  try {
    if (advance_to(0.5 * end)) o.half = sample(solver);
    if (advance_to(end)) o.end = sample(solver);
  } catch (const Error& e) {
    o.stopped = true;
    o.message = e.what();
  }
  o.steps = solver.steps();
  return o;
}

}  // namespace

bool Samples::finite() const {
  for (const auto* field : {&x, &y, &density, &speed, &pressure, &volume})
    for (const double v : *field)
      if (!std::isfinite(v)) return false;
  return true;
}

double Samples::max_pressure() const {
  double top = -INFINITY;
  for (const double p : pressure) top = std::max(top, p);
  return top;
}

double Samples::kinetic_energy() const {
  double sum = 0.0;
  for (std::size_t i = 0; i < density.size(); ++i)
    sum += 0.5 * density[i] * speed[i] * speed[i] * volume[i];
  return sum;
}

double Samples::mean_density_error(const std::function<double(double)>& exact, double x_min,
                                   double x_max) const {
  double sum = 0.0, total = 0.0;
  for (std::size_t i = 0; i < density.size(); ++i) {
    if (x[i] < x_min || x[i] > x_max) continue;
    sum += std::abs(density[i] - exact(x[i])) * volume[i];
    total += volume[i];
  }
  return total > 0.0 ? sum / total : NAN;
}

Outcome run_scene(const std::string& text, Solver solver, std::optional<double> cfl,
                  const std::filesystem::path& work) {
  if (solver == Solver::cfdmp) return run_cfdmp(text, work);
  const auto scene = config::parse_scene(text, "stability.yaml");
  if (solver == Solver::fdm) {
    auto options = fdm::SolverOptions::from_scene(scene);
    options.cfl = cfl.value_or(options.cfl);
    fdm::EulerSolver fdm(scene, options);
    return run_solver(fdm, scene.time.end, fdm_samples);
  }
  auto settings = mpm::MpmSettings::from_scene(scene);
  settings.cfl = cfl.value_or(scene.time.mpm_cfl());
  mpm::MpmSolver mpm(scene, settings);
  return run_solver(mpm, scene.time.end, mpm_samples);
}

}  // namespace mpfd::stability
