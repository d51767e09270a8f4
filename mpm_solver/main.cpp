// mpm_solver: the explicit material point method solver. `run SCENE --out DIR`
// advances a scene on its own (no coupler) and writes the layout of
// docs/output.md (a `domain.geometry: spherical` scene runs the 1D spherical
// MPM, mpm_solver/spherical/spherical_run.hpp); `serve --endpoint URL` is driven step by step by a
// coupler (proto/README.md).
#include <omp.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <exception>
#include <iostream>
#include <zmq.hpp>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "mpm_solver/serve/serve.hpp"
#include "mpm_solver/spherical/spherical_run.hpp"
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
  mpfd::mpm::ServeOptions serve_options;
  double idle_seconds = 60.0;
  auto* serve = app.add_subcommand("serve", "answer a coupler over protocol v1 (proto/README.md)");
  serve
      ->add_option("--endpoint", serve_options.endpoint,
                   "the coupler's endpoint: ipc:///path, tcp://host:port")
      ->required();
  serve->add_option("--name", serve_options.name, "routing id the coupler knows this solver by")
      ->capture_default_str();
  serve
      ->add_option("--idle-timeout", idle_seconds,
                   "seconds to wait for the coupler's next request before stopping with an error")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  serve->add_option("--threads", threads, "OpenMP threads (default: all cores)")
      ->check(CLI::PositiveNumber);
  CLI11_PARSE(app, argc, argv);

  try {
    if (threads > 0) omp_set_num_threads(threads);
    if (*serve) {
      serve_options.idle_timeout = std::chrono::milliseconds(std::llround(idle_seconds * 1e3));
      zmq::context_t context;
      mpfd::mpm::serve(context, serve_options);
      return 0;
    }
    options.scene_file = scene_file;
    options.out_dir = out_dir;
    const auto scene = mpfd::config::load_scene(scene_file);
    if (scene.domain.geometry == mpfd::config::Geometry::spherical)
      mpfd::mpm::spherical::run_spherical(scene, {scene_file, out_dir, options.overwrite});
    else
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
