// MPM throughput and memory: builds the solver for a scene, takes a number of
// steps and prints one JSON line: particles, steps, solver seconds,
// particle-updates per second (per run and per thread), and peak resident
// memory per particle. No output files are written, so the memory is the
// solver's own. The rate per CPU second uses the process's CPU time, which a
// busy shared machine does not inflate the way it inflates wall time.
// bench/run_mpm.sh runs it for 1 and 2 threads, trilinear and GIMP.

#include <omp.h>
#include <sys/resource.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <string>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace {

/// User + system CPU time of the process so far [s].
double cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) {
    return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mpm_throughput: particle-updates per second and bytes per particle"};
  std::string scene_file, shape = "linear";
  int steps = 20, threads = 1;
  app.add_option("--scene", scene_file, "scene file")->required()->check(CLI::ExistingFile);
  app.add_option("--steps", steps, "steps to time (after one warm-up step)")->capture_default_str();
  app.add_option("--threads", threads, "OpenMP threads")->capture_default_str();
  app.add_option("--shape", shape, "linear, gimp or cpgimp")
      ->check(CLI::IsMember({"linear", "gimp", "cpgimp"}));
  CLI11_PARSE(app, argc, argv);

  omp_set_num_threads(threads);
  auto scene = mpfd::config::load_scene(scene_file);
  scene.solver.mpm.shape_function = shape == "gimp"     ? mpfd::config::ShapeFunction::gimp
                                    : shape == "cpgimp" ? mpfd::config::ShapeFunction::cpgimp
                                                        : mpfd::config::ShapeFunction::linear;
  mpfd::mpm::MpmSolver solver(scene, mpfd::mpm::MpmSettings::from_scene(scene));
  solver.advance(solver.stable_dt());  // warm-up: the grid arrays reach their size
  const double updates_before = solver.particle_updates();
  const auto start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_seconds();
  for (int i = 0; i < steps; ++i) solver.advance(solver.stable_dt());
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double cpu = cpu_seconds() - cpu_start;
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const double peak = 1024.0 * static_cast<double>(usage.ru_maxrss);
  const double n = static_cast<double>(solver.particles().size());
  const double rate = (solver.particle_updates() - updates_before) / seconds;
  std::printf(
      "{\"scene\": \"%s\", \"shape_function\": \"%s\", \"threads\": %d, \"particles\": %.0f, "
      "\"steps\": %d, \"seconds\": %.4f, \"particle_updates_per_second\": %.4e, "
      "\"per_thread\": %.4e, \"cpu_seconds\": %.4f, \"per_cpu_second\": %.4e, \"peak_rss_bytes\": "
      "%.0f, \"bytes_per_particle\": %.1f, "
      "\"grid_nodes\": %zu}\n",
      scene.name.c_str(), shape.c_str(), threads, n, steps, seconds, rate, rate / threads, cpu,
      (solver.particle_updates() - updates_before) / cpu, peak, peak / n,
      solver.sparse_grid().node_count());
  return 0;
}
