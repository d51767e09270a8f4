// mpm_solver: the explicit material point method solver. `run SCENE --out DIR`
// advances a scene on its own (no coupler) and writes the layout of
// docs/output.md.
#include <omp.h>

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "mpm_solver/standalone_run.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mpm_solver: explicit material point method for explosives, gases and solids"};
  app.require_subcommand(1);
  mpfd::mpm::RunOptions options;
  std::string scene_file;
  std::string out_dir;
  int threads = 0;
  auto* run = app.add_subcommand("run", "advance a scene to its end time without a coupler");
  run->add_option("scene", scene_file, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  run->add_option("--out", out_dir, "output folder (docs/output.md)")->required();
  run->add_flag("--overwrite", options.overwrite, "reuse a folder that holds an earlier run");
  run->add_option("--threads", threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  try {
    if (threads > 0) omp_set_num_threads(threads);
    options.scene_file = scene_file;
    options.out_dir = out_dir;
    const auto scene = mpfd::config::load_scene(scene_file);
    mpfd::mpm::run_standalone(scene, options);
    std::cout << "mpm_solver: '" << scene.name << "' done; output in " << out_dir << "\n";
    return 0;
  } catch (const mpfd::Error& e) {
    std::cerr << "mpm_solver: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "mpm_solver: internal error: " << e.what() << "\n";
    return 2;
  }
}
