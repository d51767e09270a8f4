// One hard Riemann problem (hard_riemann_problems()) in the MPM with chosen
// shape function, update, grid, CFL number and bulk-viscosity coefficients:
// prints the relative L1 density error over [0, 1] m and the energy audit
// (kinetic + internal + what left through the open ends, relative change over
// the run), and with --out writes the particles in [0, 1] m with the exact
// solution beside them. The tool behind docs/stability.md's analysis of the
// MPM on strong shocks into cold gas.
//
// Sample run: build/bench/stability/stability_riemann_probe --problem pressure_ratio_1e3
//             --shape gimp --cells 400 --cfl 0.125 --out profile.csv

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/stability/mpm_tube.hpp"
#include "tests/stability/stability_cases.hpp"
#include "tests/verification/support/exact_riemann.hpp"

namespace {

/// The particles in [0, 1] m with the exact solution beside them, as CSV.
void write_profile(const std::string& path, const mpfd::mpm::ParticleSet& ps,
                   const mpfd::stability::RiemannProblem& problem) {
  std::ofstream csv(path);
  if (!csv) throw mpfd::Error("cannot write the profile '" + path + "'");
  const mpfd::verification::ExactRiemann exact(problem.left, problem.right, problem.gamma);
  csv << "x,rho,u,p,e,q,mass,exact_rho,exact_u,exact_p\n";
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double x = ps.position[0][p];
    if (x < 0.0 || x > 1.0) continue;
    const auto ex = exact.sample((x - 0.5) / problem.end);
    csv << x << ',' << ps.density[p] << ',' << ps.velocity[0][p] << ',' << ps.pressure[p] << ','
        << ps.specific_internal_energy[p] << ',' << ps.bulk_viscosity[p] << ',' << ps.mass[p] << ','
        << ex.density << ',' << ex.velocity << ',' << ex.pressure << '\n';
  }
  if (!csv.flush()) throw mpfd::Error("writing the profile '" + path + "' failed");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace mpfd;
  using namespace mpfd::stability;
  CLI::App app{"stability_riemann_probe: one hard Riemann problem in the MPM, error and energy"};
  std::string name = "pressure_ratio_1e3", shape = "linear", update = "musl", out;
  int cells = 200;
  double cfl = config::kMpmDefaultCfl, c0 = 1.5, c1 = 0.06;
  app.add_option("--problem", name, "a name of hard_riemann_problems()")->capture_default_str();
  app.add_option("--shape", shape, "linear or gimp")
      ->check(CLI::IsMember({"linear", "gimp"}))
      ->capture_default_str();
  app.add_option("--update", update, "musl, usl or usavg")
      ->check(CLI::IsMember({"musl", "usl", "usavg"}))
      ->capture_default_str();
  app.add_option("--cells", cells, "cells per metre")->capture_default_str();
  app.add_option("--cfl", cfl, "Courant number")->capture_default_str();
  app.add_option("--c0", c0, "quadratic bulk-viscosity coefficient")->capture_default_str();
  app.add_option("--c1", c1, "linear bulk-viscosity coefficient")->capture_default_str();
  app.add_option("--out", out, "CSV of the particles in [0, 1] m");
  CLI11_PARSE(app, argc, argv);
  RiemannProblem problem;
  try {
    problem = hard_riemann_problem(name);
  } catch (const Error& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  const Solver solver = shape == "gimp" ? Solver::mpm_gimp : Solver::mpm_linear;
  const auto scene = config::parse_scene(tube_scene(problem, cells, solver, cfl), "probe.yaml");
  auto settings = mpm::MpmSettings::from_scene(scene);
  settings.cfl = cfl;
  settings.bulk_viscosity_quadratic = c0;
  settings.bulk_viscosity_linear = c1;
  settings.update = update == "usl"     ? config::MpmUpdate::usl
                    : update == "usavg" ? config::MpmUpdate::usavg
                                        : config::MpmUpdate::musl;
  try {
    mpm::MpmSolver mpm(scene, settings);
    const double e0 = audited_energy(mpm);
    mpm.advance_to(problem.end);
    const double e1 = audited_energy(mpm);
    const auto& ps = mpm.particles();
    if (!out.empty()) write_profile(out, ps, problem);
    std::printf("%s %s %s %d cells cfl %.4g c0 %.3g c1 %.3g: %lld steps, L1 %.4f, energy %+.3e\n",
                name.c_str(), shape.c_str(), update.c_str(), cells, cfl, c0, c1,
                static_cast<long long>(mpm.steps()), particle_l1_density(ps, problem),
                (e1 - e0) / e0);
  } catch (const Error& e) {
    std::printf("%s %s %s %d cells cfl %.4g: stopped: %s\n", name.c_str(), shape.c_str(),
                update.c_str(), cells, cfl, e.what());
    return 1;
  }
  return 0;
}
