// coupler: runs a CFDMP (T §4.3) or AFDMP (T chapter 3) scene by driving
// `fdm_solver serve` and `mpm_solver serve` over protocol v1 (proto/README.md).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>

#include "common/core/error.hpp"
#include "coupler/run/launch.hpp"
#include "coupler/run/replay.hpp"

int main(int argc, char** argv) {
  CLI::App app{"coupler: CFDMP and AFDMP co-simulation of the FDM and MPM solvers"};
  app.require_subcommand(1);
  std::string scene_file, out_dir, record, endpoints;
  bool processes = false;
  mpfd::coupler::LaunchOptions launch;
  std::string fdm_program, mpm_program;
  auto* run = app.add_subcommand("run", "run a cfdmp or afdmp scene to its end time");
  run->add_option("scene", scene_file, "scene file (YAML), solver.method cfdmp or afdmp")
      ->required()
      ->check(CLI::ExistingFile);
  run->add_option("--out", out_dir, "output folder (summary.json, fdm/, mpm/)")->required();
  run->add_flag("--overwrite", launch.overwrite, "reuse a folder that holds an earlier run");
  run->add_option("--record", record, "record every message to FILE (.mpfdrec, proto §10)");
  int checkpoint_every = 0;
  run->add_option("--checkpoint-every", checkpoint_every,
                  "checkpoint the solvers and the coupler after every K-th output "
                  "(<out>/checkpoints, fdm/checkpoints, mpm/checkpoints); 0: none")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  int checkpoint_keep = 2;
  run->add_option("--checkpoint-keep", checkpoint_keep,
                  "keep the newest N checkpoints; each older one goes with the solver files "
                  "only it names (those in --out); 0: keep all")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
  run->add_flag("--restart", launch.restart,
                "go on with the run in --out from its newest checkpoint (same scene file)");
  run->add_flag("--processes", processes, "start the solvers as child processes (over ipc)");
  run->add_option("--endpoints", endpoints,
                  "fdm=URL,mpm=URL: bind these (with --processes the children connect to them; "
                  "without, solvers started elsewhere do)");
  run->add_option("--timeout", launch.timeout_seconds, "seconds to wait for each reply")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  double chunk_mib = 64, handoff_timeout = 300;
  run->add_option("--chunk-mib", chunk_mib,
                  "afdmp: largest piece of a whole-field handoff message, MiB (proto §15)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  run->add_option("--handoff-timeout", handoff_timeout,
                  "afdmp: seconds to wait for each piece and commit of a handoff")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  run->add_option("--fdm-program", fdm_program, "fdm_solver to start (default: beside coupler)");
  run->add_option("--mpm-program", mpm_program, "mpm_solver to start (default: beside coupler)");
  mpfd::coupler::ReplayOptions replay_options;
  std::string recording, replay_out;
  auto* replay = app.add_subcommand(
      "replay", "play a recorded run's coupler side against one live solver and compare replies");
  replay->add_option("file", recording, "recording (.mpfdrec)")
      ->required()
      ->check(CLI::ExistingFile);
  replay->add_option("--solver", replay_options.solver, "the solver to replay")
      ->required()
      ->check(CLI::IsMember({"fdm", "mpm"}));
  replay->add_option("--tolerance", replay_options.tolerance,
                     "relative tolerance for values (default 0: bitwise)");
  replay->add_option("--out", replay_out,
                     "folder for the solver's output (default: a temp folder)");
  CLI11_PARSE(app, argc, argv);

  if (*replay) {
    try {
      replay_options.out_dir = replay_out.empty()
                                   ? std::filesystem::temp_directory_path() /
                                         ("mpfd-replay-" + std::to_string(::getpid()))
                                   : std::filesystem::path(replay_out);
      const auto report = mpfd::coupler::replay(
          recording, replay_options, mpfd::coupler::embedded_serve(replay_options.solver));
      if (report.divergence) {
        std::cout << "replay of '" << replay_options.solver << "': first divergence at "
                  << *report.divergence << "\n";
        return 2;
      }
      std::cout << "replay of '" << replay_options.solver << "': " << report.requests
                << " requests, " << report.values_compared
                << " array values, every reply identical to the recording\n";
      return 0;
    } catch (const std::exception& error) {
      std::cerr << "coupler: " << error.what() << "\n";
      return 1;
    }
  }

  try {
    if (!endpoints.empty()) launch.endpoints = mpfd::coupler::parse_endpoint_list(endpoints);
    launch.mode = processes            ? mpfd::coupler::LaunchMode::processes
                  : !endpoints.empty() ? mpfd::coupler::LaunchMode::external
                                       : mpfd::coupler::LaunchMode::embedded;
    launch.fdm_program = fdm_program;
    launch.mpm_program = mpm_program;
    mpfd::coupler::CoupledRunOptions options;
    options.out_dir = out_dir;
    options.checkpoint_every = checkpoint_every;
    options.checkpoint_keep = checkpoint_keep;
    if (!record.empty()) options.record = record;
    options.max_chunk_bytes = static_cast<std::uint64_t>(chunk_mib * 1024 * 1024);
    options.handoff_timeout = std::chrono::milliseconds(std::llround(handoff_timeout * 1e3));
    mpfd::coupler::launch_run(scene_file, launch, options, argv[0]);
    return 0;
  } catch (const std::exception& error) {
    std::cerr << "coupler: " << error.what() << "\n";
    return 1;
  }
}
