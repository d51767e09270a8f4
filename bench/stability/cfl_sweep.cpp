// The time-step part of the stability suite (issue 7): for each solver (FDM,
// MPM linear, MPM GIMP, CFDMP) and case (Sod's tube, a small 2D TNT blast)
// runs the CFL numbers 0.1, 0.2, ... up to --max-cfl and bisects twice
// between the last stable and the first unstable one (0.025 resolution).
// Stable as judged by tests/stability/stability_cases.hpp against the CFL 0.1
// run. CFDMP takes its CFL from the scene file, which allows at most 1.
// Writes <out>/cfl_runs.csv (every run) and <out>/cfl_limits.csv (per solver
// and case: the largest CFL up to which every run was stable, and the verdict
// of the first unstable one, and what is wrong with the CFL 0.1 run if
// anything: a defect no time step cures).
//
// Sample run: build/bench/stability/stability_cfl_sweep --out bench/stability/results

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "tests/stability/stability_cases.hpp"

namespace {

using namespace mpfd::stability;

std::string csv_text(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  std::replace(text.begin(), text.end(), '\n', ' ');
  return '"' + text + '"';
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"stability_cfl_sweep: the largest stable CFL per solver and case"};
  std::string out;
  double max_cfl = 1.2;
  std::vector<std::string> only;
  app.add_option("--out", out, "folder for cfl_runs.csv and cfl_limits.csv")->required();
  app.add_option("--max-cfl", max_cfl, "largest CFL of the coarse sweep")->capture_default_str();
  app.add_option("--only", only, "solver names to run (fdm mpm_linear mpm_gimp cfdmp)");
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const auto work =
      std::filesystem::temp_directory_path() / ("mpfd-stability-cfl-" + std::to_string(::getpid()));

  std::ofstream runs(std::filesystem::path(out) / "cfl_runs.csv");
  runs << "solver,case,cfl,steps,verdict,measures\n";
  std::ofstream limits(std::filesystem::path(out) / "cfl_limits.csv");
  limits << "solver,case,largest_stable_cfl,first_unstable_cfl,first_unstable_verdict,"
            "reference_defect\n";

  for (const Solver solver : {Solver::fdm, Solver::mpm_linear, Solver::mpm_gimp, Solver::cfdmp}) {
    if (!only.empty() && std::find(only.begin(), only.end(), solver_name(solver)) == only.end())
      continue;
    const double top = solver == Solver::cfdmp ? std::min(max_cfl, 1.0) : max_cfl;
    for (const SweepCase c : {SweepCase::sod, SweepCase::acoustic, SweepCase::blast_2d}) {
      const auto run = [&](double cfl) {
        return run_scene(sweep_scene(c, solver, cfl), solver, cfl, work);
      };
      const Outcome reference = run(kReferenceCfl);
      const auto judge = [&](double cfl) {
        const Outcome o = cfl == kReferenceCfl ? reference : run(cfl);
        const SweepVerdict verdict = judge_sweep(c, o, reference);
        runs << solver_name(solver) << ',' << case_name(c) << ',' << cfl << ',' << o.steps << ','
             << (verdict.stable ? "stable" : "unstable") << ',' << csv_text(verdict.text) << '\n';
        runs.flush();
        std::printf("%-10s %-8s cfl %.3f: %6lld steps, %s: %s\n", solver_name(solver), case_name(c),
                    cfl, static_cast<long long>(o.steps), verdict.stable ? "stable" : "UNSTABLE",
                    verdict.text.c_str());
        std::fflush(stdout);
        return verdict;
      };
      double stable = 0.0, unstable = 0.0;
      std::string first_bad;
      for (int k = 1; k * 0.1 <= top + 1e-9; ++k) {
        const double cfl = k * 0.1;
        const SweepVerdict verdict = judge(cfl);
        if (!verdict.stable) {
          unstable = cfl, first_bad = verdict.text;
          break;
        }
        stable = cfl;
      }
      for (int halving = 0; halving < 2 && unstable > 0.0 && stable > 0.0; ++halving) {
        const double middle = 0.5 * (stable + unstable);
        const SweepVerdict verdict = judge(middle);
        if (verdict.stable)
          stable = middle;
        else
          unstable = middle, first_bad = verdict.text;
      }
      limits << solver_name(solver) << ',' << case_name(c) << ',' << stable << ',';
      if (unstable > 0.0)
        limits << unstable << ',' << csv_text(first_bad);
      else
        limits << ",\"stable up to " << top << '"';
      limits << ',' << csv_text(reference_defect(c, reference)) << '\n';
      limits.flush();
    }
  }
  std::filesystem::remove_all(work);
  return 0;
}
