#pragma once
// Helpers of the config tests: a minimal valid scene to build broken ones
// from, and the messages a scene's SceneError carries.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/config/scene_loader.hpp"

namespace mpfd::config::test {

/// The repository's ready scenes.
inline const std::filesystem::path kConfigs = std::filesystem::path(MPFD_SOURCE_DIR) / "configs";

/// A minimal valid 1D scene: thesis air at rest in a 1 m tube.
inline const std::string kMinimalScene = R"(name: tube
time: {end: 1.0e-3}
domain: {lower: [0, 0, 0], upper: [1, 0.1, 0.1], cells: [10, 1, 1]}
materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
output: {interval: 1.0e-4}
)";

/// Every message of the SceneError that parsing `yaml` throws (empty, and a
/// test failure, if it parses).
inline std::vector<std::string> errors_of(std::string_view yaml) {
  try {
    parse_scene(yaml, "scene.yaml");
  } catch (const SceneError& e) {
    std::vector<std::string> lines;
    for (const Diagnostic& d : e.diagnostics()) lines.push_back(to_string(d));
    return lines;
  }
  ADD_FAILURE() << "the scene parsed but should not have:\n" << yaml;
  return {};
}

/// The only error of `yaml` is at `path` and says `says`.
inline void expect_one(const std::string& yaml, const std::string& path, const std::string& says) {
  using ::testing::HasSubstr;
  EXPECT_THAT(errors_of(yaml), ::testing::ElementsAre(::testing::AllOf(
                                   ::testing::StartsWith("scene.yaml:"),
                                   HasSubstr(": " + path + ": "), HasSubstr(says))));
}

}  // namespace mpfd::config::test
