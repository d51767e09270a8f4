// fdm_solver: the FDM Euler solver. `run SCENE --out DIR` advances a scene
// on its own (no coupler) and writes the layout of docs/output.md.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "fdm_solver/standalone_run.hpp"

int main(int argc, char** argv) {
  CLI::App app{"fdm_solver: shock-capturing Euler solver for air and detonation products"};
  app.require_subcommand(1);
  mpfd::fdm::RunOptions options;
  std::string scene_file;
  std::string out_dir;
  int threads = 0;
  bool full_grid = false;
  auto* run = app.add_subcommand("run", "advance a scene to its end time without a coupler");
  run->add_option("scene", scene_file, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  run->add_option("--out", out_dir, "output folder (docs/output.md)")->required();
  run->add_flag("--overwrite", options.overwrite, "reuse a folder that holds an earlier run");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  run->add_flag("--full-grid", full_grid,
                "update every cell each step instead of only the disturbed region "
                "(same result, for comparisons)");
  CLI11_PARSE(app, argc, argv);

  try {
    if (threads > 0) omp_set_num_threads(threads);
    options.scene_file = scene_file;
    options.out_dir = out_dir;
    options.skip_quiet = !full_grid;
    const auto scene = mpfd::config::load_scene(scene_file);
    mpfd::fdm::run_standalone(scene, options);
    std::cout << "fdm_solver: '" << scene.name << "' done; output in " << out_dir << "\n";
    return 0;
  } catch (const mpfd::Error& e) {
    std::cerr << "fdm_solver: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "fdm_solver: internal error: " << e.what() << "\n";
    return 2;
  }
}
