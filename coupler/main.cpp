// coupler: runs a CFDMP scene (T §4.3) by driving `fdm_solver serve` and
// `mpm_solver serve` over protocol v1 (proto/README.md).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "common/core/error.hpp"
#include "coupler/run/launch.hpp"

int main(int argc, char** argv) {
  CLI::App app{"coupler: CFDMP co-simulation of the FDM and MPM solvers"};
  app.require_subcommand(1);
  std::string scene_file, out_dir, record, endpoints;
  bool processes = false;
  mpfd::coupler::LaunchOptions launch;
  std::string fdm_program, mpm_program;
  auto* run = app.add_subcommand("run", "run a cfdmp scene to its end time");
  run->add_option("scene", scene_file, "scene file (YAML), solver.method cfdmp")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("--out", out_dir, "output folder (summary.json, fdm/, mpm/)")->required();
  run->add_flag("--overwrite", launch.overwrite, "reuse a folder that holds an earlier run");
  run->add_option("--record", record, "record every message to FILE (.mpfdrec, proto §10)");
  run->add_flag("--processes", processes, "start the solvers as child processes (over ipc)");
  run->add_option("--endpoints", endpoints,
                  "fdm=URL,mpm=URL: bind these (with --processes the children connect to them; "
                  "without, solvers started elsewhere do)");
  run->add_option("--timeout", launch.timeout_seconds, "seconds to wait for each reply")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  run->add_option("--fdm-program", fdm_program, "fdm_solver to start (default: beside coupler)");
  run->add_option("--mpm-program", mpm_program, "mpm_solver to start (default: beside coupler)");
  CLI11_PARSE(app, argc, argv);

  try {
    if (!endpoints.empty()) launch.endpoints = mpfd::coupler::parse_endpoint_list(endpoints);
    launch.mode = processes            ? mpfd::coupler::LaunchMode::processes
                  : !endpoints.empty() ? mpfd::coupler::LaunchMode::external
                                       : mpfd::coupler::LaunchMode::embedded;
    launch.fdm_program = fdm_program;
    launch.mpm_program = mpm_program;
    mpfd::coupler::CoupledRunOptions options;
    options.out_dir = out_dir;
    if (!record.empty()) options.record = record;
    mpfd::coupler::launch_run(scene_file, launch, options, argv[0]);
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "coupler: " << error.what() << "\n";
    return 1;
  }
}
