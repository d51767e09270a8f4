// The hard-Riemann part of the stability suite (issue 7): every problem of
// hard_riemann_problems() and the JWL-products-against-air tube, in FDM, MPM
// (linear and GIMP) and across the CFDMP zone boundary (the diaphragm 0.1 m
// inside the FDM zone), at each solver's default CFL, on two grids (N and 2N
// cells per metre). Each run either matches
// its reference (relative L1 density error within --tolerance) or stops with
// mpfd::Error; anything else is a silent failure and makes the exit code 1.
// Writes <out>/riemann.csv.
//
// Sample run: build/bench/stability/stability_riemann_suite --out bench/stability/results

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>

#include "common/config/scene.hpp"
#include "tests/stability/stability_cases.hpp"
#include "tests/verification/support/exact_riemann.hpp"

namespace {

using namespace mpfd::stability;

std::string csv_text(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  std::replace(text.begin(), text.end(), '\n', ' ');
  return '"' + text + '"';
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"stability_riemann_suite: hard Riemann problems match or stop loudly"};
  std::string out, source = MPFD_SOURCE_DIR;
  int cells = 200;
  std::optional<double> cfl;
  app.add_option("--out", out, "folder for riemann.csv")->required();
  app.add_option("--cells", cells,
                 "cells per metre of the FDM and MPM tubes (CFDMP: 100), and twice")
      ->capture_default_str();
  app.add_option("--cfl", cfl, "Courant number (default: each solver's default)");
  std::string update = "musl";
  app.add_option("--update", update,
                 "solver.mpm.update of the MPM tubes: musl, usl or usavg (not musl: MPM only)")
      ->check(CLI::IsMember({"musl", "usl", "usavg"}))
      ->capture_default_str();
  bool mpm_only = false;
  app.add_flag("--mpm-only", mpm_only, "run only the MPM tubes (linear and GIMP)");
  CLI11_PARSE(app, argc, argv);
  // The scenes name musl; another update replaces it (usavg is MPM-only, so FDM
  // and CFDMP are left out then).
  const auto with_update = [&](std::string text) {
    const std::string key = "update: musl";
    if (const auto at = text.find(key); at != std::string::npos)
      text.replace(at, key.size(), "update: " + update);
    return text;
  };
  std::filesystem::create_directories(out);
  const auto work = std::filesystem::temp_directory_path() /
                    ("mpfd-stability-riemann-" + std::to_string(::getpid()));

  std::ofstream csv(std::filesystem::path(out) / "riemann.csv");
  csv << "problem,solver,cells,cfl,steps,tolerance,l1_density,silent_failure,verdict\n";
  int silent = 0;
  const auto record = [&](const std::string& problem, Solver solver, int n, const Outcome& o,
                          double tolerance, const std::function<double(double)>& exact,
                          double scale, double x_max) {
    const RiemannVerdict v = judge_riemann(o, tolerance, exact, scale, 0.0, x_max);
    silent += v.silent_failure ? 1 : 0;
    csv << problem << ',' << solver_name(solver) << ',' << n << ','
        << (cfl ? std::to_string(*cfl) : std::string("default")) << ',' << o.steps << ','
        << tolerance << ',' << v.error << ',' << (v.silent_failure ? 1 : 0) << ','
        << csv_text(v.text) << '\n';
    csv.flush();
    std::printf("%-20s %-10s %5d cells %6lld steps  L1 %.3e  %s%s\n", problem.c_str(),
                solver_name(solver), n, static_cast<long long>(o.steps), v.error,
                v.silent_failure ? "SILENT: " : "", v.text.c_str());
    std::fflush(stdout);
  };
  for (const Solver solver : {Solver::fdm, Solver::mpm_linear, Solver::mpm_gimp, Solver::cfdmp}) {
    const bool is_mpm = solver == Solver::mpm_linear || solver == Solver::mpm_gimp;
    if ((mpm_only || update != "musl") && !is_mpm) continue;
    const int coarse = solver == Solver::cfdmp ? 100 : cells;
    for (const RiemannProblem& p : hard_riemann_problems()) {
      const mpfd::verification::ExactRiemann exact(p.left, p.right, p.gamma);
      // The finer grid shows whether the error falls as a match's must.
      for (const int n : {coarse, 2 * coarse}) {
        const Outcome o = run_scene(with_update(tube_scene(p, n, solver, cfl)), solver, cfl, work);
        record(
            p.name, solver, n, o, riemann_tolerance(p.name, solver),
            [&](double x) { return exact.sample((x - 0.5) / p.end).density; },
            std::max(p.left.density, p.right.density), 1.0);
      }
    }
    const Outcome o = run_scene(with_update(jwl_air_tube_scene(solver, cfl)), solver, cfl, work);
    record("jwl_products_air", solver, 500, o, riemann_tolerance("jwl_products_air", solver),
           jwl_air_tube_reference(source), 2227.47, 0.5);
  }
  std::filesystem::remove_all(work);
  return silent == 0 ? 0 : 1;
}
