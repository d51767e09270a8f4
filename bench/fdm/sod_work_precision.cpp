// Work-precision benchmark of the FDM solver on Sod's shock tube (V1 of
// METHOD.md: gamma 1.4, (1, 0, 1) | (0.125, 0, 0.1), diaphragm at x = 0.5,
// outflow ends, t = 0.2): for each CFL number and each grid of N cells, the
// solver's wall time (best of --repeats, the time loop only) against the L1
// errors of density, velocity and pressure at cell centres versus the exact
// Riemann solution (tests/verification/support/). Writes one CSV line per run:
//   cfl,cells,steps,wall_s,l1_density,l1_velocity,l1_pressure
// Plot it with tools/plot_work_precision.py; bench/run_fdm.sh runs both.
//
// Sample run: build/bench/fdm/sod_work_precision --out /tmp/sod_wp.csv --max-cells 800

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "tests/verification/support/exact_riemann.hpp"
#include "tests/verification/support/norms.hpp"

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kEnd = 0.2;        // [s], the usual Sod comparison time
constexpr double kDiaphragm = 0.5;  // [m]
constexpr double kGamma = 1.4;

/// Sod's tube along x with `cells` cells (one cell in y and z), from scene text
/// so that the benchmark goes through the same parser as users.
mpfd::config::Scene sod_scene(int cells, double cfl) {
  const std::string text =
      "name: sod_work_precision\n"
      "time: {end: 0.2, cfl: " +
      std::to_string(cfl) +
      "}\n"
      "domain: {lower: [0, 0, 0], upper: [1, 1, 1], cells: [" +
      std::to_string(cells) +
      ", 1, 1]}\n"
      "materials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: {material: gas, density: 0.125, pressure: 0.1}\n"
      "bodies:\n"
      "  - {name: left, material: gas, density: 1.0, pressure: 1.0,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [0.5, 1, 1]}}}\n"
      "boundaries: {x_lower: outflow, x_upper: outflow}\n"
      "output: {interval: 1.0}\n";
  return mpfd::config::parse_scene(text, "sod_work_precision.yaml");
}

struct Result {
  int steps = 0;
  double wall_s = std::numeric_limits<double>::infinity();
  double l1_density = 0.0, l1_velocity = 0.0, l1_pressure = 0.0;
};

/// Advances to kEnd as the standalone run does; returns the wall time of the
/// time loop [s].
double run_to_end(mpfd::fdm::EulerSolver& solver) {
  const auto start = Clock::now();
  solver.advance_to(kEnd);
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Result measure(int cells, double cfl, int repeats) {
  const auto scene = sod_scene(cells, cfl);
  Result r;
  for (int k = 0; k < repeats; ++k) {
    mpfd::fdm::EulerSolver solver(scene, {.cfl = cfl, .viscosity = 1.0, .skip_quiet = true});
    r.wall_s = std::min(r.wall_s, run_to_end(solver));
    if (k + 1 < repeats) continue;
    r.steps = static_cast<int>(solver.steps());
    const auto& u = solver.state().u;
    const std::vector<double>& rho = u[mpfd::fdm::kDensity];
    std::vector<double> vel(rho.size()), p(rho.size());
    for (std::size_t i = 0; i < rho.size(); ++i) {
      vel[i] = u[mpfd::fdm::kMomentumX][i] / rho[i];
      p[i] =
          (kGamma - 1.0) * (u[mpfd::fdm::kEnergy][i] - 0.5 * rho[i] * vel[i] * vel[i]);  // T (2-59)
    }
    const mpfd::verification::ExactRiemann exact({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, kGamma);
    const auto at = [&](auto member) {
      return [&, member](double x) { return exact.sample((x - kDiaphragm) / kEnd).*member; };
    };
    using S = mpfd::verification::PrimitiveState;
    r.l1_density = mpfd::verification::l1_error_at_centres(rho, 0.0, 1.0, at(&S::density));
    r.l1_velocity = mpfd::verification::l1_error_at_centres(vel, 0.0, 1.0, at(&S::velocity));
    r.l1_pressure = mpfd::verification::l1_error_at_centres(p, 0.0, 1.0, at(&S::pressure));
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"sod_work_precision: FDM wall time against L1 error on Sod's tube"};
  std::string out;
  int max_cells = 3200;
  int repeats = 3;
  app.add_option("--out", out, "CSV file to write")->required();
  app.add_option("--max-cells", max_cells, "largest N of 100, 200, 400, ... (default 3200)")
      ->check(CLI::Range(100, 1 << 20));
  app.add_option("--repeats", repeats, "runs per point; the fastest counts (default 3)")
      ->check(CLI::Range(1, 100));
  CLI11_PARSE(app, argc, argv);

  try {
    std::ofstream csv(out);
    if (!csv) throw mpfd::Error("sod_work_precision: cannot write --out '" + out + "'");
    csv << "cfl,cells,steps,wall_s,l1_density,l1_velocity,l1_pressure\n";
    std::printf("%5s %6s %6s %11s %11s %11s %11s\n", "cfl", "N", "steps", "wall [s]", "L1(rho)",
                "L1(u)", "L1(p)");
    for (const double cfl : {0.3, 0.5, 0.8}) {
      for (int n = 100; n <= max_cells; n *= 2) {
        const Result r = measure(n, cfl, repeats);
        char line[160];
        std::snprintf(line, sizeof line, "%.1f,%d,%d,%.6e,%.6e,%.6e,%.6e\n", cfl, n, r.steps,
                      r.wall_s, r.l1_density, r.l1_velocity, r.l1_pressure);
        csv << line;
        std::printf("%5.1f %6d %6d %11.4e %11.4e %11.4e %11.4e\n", cfl, n, r.steps, r.wall_s,
                    r.l1_density, r.l1_velocity, r.l1_pressure);
        std::fflush(stdout);
      }
    }
    if (!csv.flush()) throw mpfd::Error("sod_work_precision: writing '" + out + "' failed");
    return 0;
  } catch (const mpfd::Error& e) {
    std::cerr << "sod_work_precision: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "sod_work_precision: internal error: " << e.what() << "\n";
    return 2;
  }
}
