// mpfd_scene: check a scene file, print the scene-file reference, or write a
// scene's initial state in the documented output layout (docs/output.md).
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "tools/scene/scene_commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"mpfd_scene: check MPFD scene files and write their initial state"};
  app.require_subcommand(1);
  std::string scene_file;
  std::string out_dir;
  bool overwrite = false;

  auto* check = app.add_subcommand("check", "validate a scene and print what it holds");
  check->add_option("scene", scene_file, "scene file (YAML)")->required();
  app.add_subcommand("schema", "print every scene key: type, unit, range, default (Markdown)");
  auto* init =
      app.add_subcommand("init", "write the scene's initial state (snapshot 0, gauges, summary)");
  init->add_option("scene", scene_file, "scene file (YAML)")->required();
  init->add_option("--out", out_dir, "output folder")->required();
  init->add_flag("--overwrite", overwrite, "reuse a folder that holds an earlier run");
  CLI11_PARSE(app, argc, argv);

  try {
    if (app.got_subcommand("schema")) {
      std::cout << mpfd::config::print_schema();
      return 0;
    }
    const auto scene = mpfd::config::load_scene(scene_file);
    if (*check) {
      mpfd::tools::describe_scene(scene, std::cout);
      std::cout << scene_file << ": valid\n";
      return 0;
    }
    mpfd::tools::write_initial_state(scene, scene_file, out_dir, overwrite);
    std::cout << "initial state of '" << scene.name << "' written to " << out_dir << "\n";
    return 0;
  } catch (const mpfd::Error& e) {
    std::cerr << "mpfd_scene: error: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "mpfd_scene: internal error: " << e.what() << "\n";
    return 2;
  }
}
