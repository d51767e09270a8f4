// Work-precision benchmark of the MPM solver on two verification cases, for
// several resolutions (2 particles per cell, the scene files' CFL 0.1):
// * sod: Sod's tube (configs/sod_mpm.yaml), particle L1 error of density at
//   t = 0.2 against the exact Riemann solution (as tests/verification/mpm/
//   sod_mpm_test.cpp), GIMP and cpGIMP;
// * tnt_slab: the V2 slab (configs/tnt_slab_1d.yaml), the largest relative
//   deviation from the CJ pressure of the JWL fit, 20.99 GPa, of the front's
//   peak (the largest particle pressure each step) once the front has run
//   20 mm and before it reaches 95 mm, GIMP.
// Wall time is the time loop only. Writes one CSV line per run:
//   case,shape_function,cells,steps,wall_s,error
// Plot it with tools/plot_mpm_work_precision.py; bench/run_mpm.sh runs both.
//
// Sample run: build/bench/mpm/mpm_work_precision --out /tmp/mpm_wp.csv

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/verification/support/exact_riemann.hpp"

namespace {

using Clock = std::chrono::steady_clock;
using mpfd::config::ShapeFunction;
constexpr double kCjPressure = 20.99e9;  // [Pa], CJ of T Table 3.1's JWL fit

struct Run {
  long long steps = 0;
  double wall_s = 0.0;
  double error = 0.0;
};

Run sod(const std::string& source, int cells, ShapeFunction shape) {
  auto scene = mpfd::config::load_scene(source + "/configs/sod_mpm.yaml");
  scene.domain.cells[0] = cells;
  scene.solver.mpm.shape_function = shape;
  mpfd::mpm::MpmSolver solver(scene, mpfd::mpm::MpmSettings::from_scene(scene));
  constexpr double kEnd = 0.2;
  const auto start = Clock::now();
  solver.advance_to(kEnd);
  Run r{solver.steps(), std::chrono::duration<double>(Clock::now() - start).count(), 0.0};
  const mpfd::verification::ExactRiemann exact({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const auto& ps = solver.particles();
  double volume = 0.0;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double v = ps.mass[p] / ps.density[p];
    r.error += std::abs(ps.density[p] - exact.sample((ps.position[0][p] - 0.5) / kEnd).density) * v;
    volume += v;
  }
  r.error /= volume;
  return r;
}

Run slab(const std::string& source, int cells) {
  auto scene = mpfd::config::load_scene(source + "/configs/tnt_slab_1d.yaml");
  scene.domain.cells[0] = cells;
  mpfd::mpm::MpmSolver solver(scene, mpfd::mpm::MpmSettings::from_scene(scene));
  constexpr double kEnd = 1.3e-5;  // the front at 90 mm
  double deviation = 0.0, wall = 0.0;
  while (solver.time() < kEnd) {
    const auto start = Clock::now();
    solver.advance(solver.step_toward(kEnd));
    wall += std::chrono::duration<double>(Clock::now() - start).count();
    const auto& ps = solver.particles();
    const auto top = static_cast<std::size_t>(
        std::max_element(ps.pressure.begin(), ps.pressure.end()) - ps.pressure.begin());
    const double x = ps.position[0][top];
    if (x >= 0.02 && x <= 0.095)
      deviation = std::max(deviation, std::abs(ps.pressure[top] - kCjPressure) / kCjPressure);
  }
  return {solver.steps(), wall, deviation};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"mpm_work_precision: error against wall time, Sod and the V2 TNT slab"};
  std::string out, source = MPFD_SOURCE_DIR;
  int max_cells = 800;
  app.add_option("--out", out, "CSV file to write")->required();
  app.add_option("--max-cells", max_cells, "largest Sod grid (the slab goes to 2.5x)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::ofstream csv(out);
  csv << "case,shape_function,cells,steps,wall_s,error\n";
  const auto write = [&](const char* name, ShapeFunction shape, int cells, const Run& r) {
    csv << name << ',' << mpfd::mpm::shape_function_name(shape) << ',' << cells << ',' << r.steps
        << ',' << r.wall_s << ',' << r.error << '\n';
    csv.flush();
    std::printf("%-8s %-7s N = %5d: %7lld steps, %8.3f s, error %.4e\n", name,
                mpfd::mpm::shape_function_name(shape), cells, r.steps, r.wall_s, r.error);
  };
  for (const ShapeFunction shape : {ShapeFunction::gimp, ShapeFunction::cpgimp})
    for (int cells = 100; cells <= max_cells; cells *= 2)
      write("sod", shape, cells, sod(source, cells, shape));
  for (int cells = 250; cells <= max_cells * 5 / 2; cells *= 2)
    write("tnt_slab", ShapeFunction::gimp, cells, slab(source, cells));
  return 0;
}
