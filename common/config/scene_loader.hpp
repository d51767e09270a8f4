#pragma once
// Loading a scene file. Every problem in the file (YAML syntax, unknown or
// missing keys, wrong types, out-of-range values, undefined references,
// points outside the domain) is collected and thrown as one SceneError, so a
// run stops before it writes anything.

#include <filesystem>
#include <string>
#include <string_view>

#include "common/config/scene.hpp"
#include "common/config/scene_error.hpp"

namespace mpfd::config {

/// Reads and validates a scene file; throws SceneError.
Scene load_scene(const std::filesystem::path& file);

/// As load_scene, from text; `file_name` is what messages call the file.
Scene parse_scene(std::string_view yaml_text, std::string_view file_name);

/// The reference of every key (markdown), generated from the schema; checked in as
/// configs/SCENE-REFERENCE.md.
std::string print_schema();

}  // namespace mpfd::config
