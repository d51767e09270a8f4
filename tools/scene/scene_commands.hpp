#pragma once
// The scene tool's commands, apart from argument parsing so tests can call
// them: describe a scene, and write its initial state in the output layout of
// docs/output.md.

#include <filesystem>
#include <iosfwd>

#include "common/config/scene.hpp"

namespace mpfd::tools {

/// Prints what the scene holds: grid, materials (with the CJ state of every
/// explosive), bodies, charges, boundaries, gauges, output.
void describe_scene(const config::Scene& scene, std::ostream& out);

/// Writes the scene's initial state to `out_dir`: snapshot 0 with its XDMF
/// sidecar, the gauges sampled at t = 0, and summary.json. Nothing is written
/// if the folder holds an earlier run and `overwrite` is false.
void write_initial_state(const config::Scene& scene, const std::filesystem::path& scene_file,
                         const std::filesystem::path& out_dir, bool overwrite);

}  // namespace mpfd::tools
