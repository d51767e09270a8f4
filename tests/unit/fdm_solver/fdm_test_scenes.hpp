#pragma once
// Small scenes for the FDM solver tests, written as scene files so that the
// tests go through the same parser as users.

#include <string>

#include "common/config/scene_loader.hpp"

namespace mpfd::fdm::testing {

/// A scene of ideal gas (gamma 1.4): `domain` and `cells` as YAML lists, the
/// background `initial` state and any `extra` top-level YAML (bodies,
/// boundaries) given as text.
inline config::Scene gas_scene(const std::string& upper, const std::string& cells,
                               const std::string& initial, const std::string& extra = "") {
  const std::string text =
      "name: test\ntime: {end: 1.0}\n"
      "domain: {lower: [0, 0, 0], upper: " +
      upper + ", cells: " + cells +
      "}\nmaterials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: " +
      initial + "\noutput: {interval: 1.0}\n" + extra;
  return config::parse_scene(text, "test.yaml");
}

/// Sod's tube (V1) along `axis` (0, 1, 2) with `n` cells, walls on the other faces.
inline config::Scene sod_tube(int axis, int n) {
  std::string upper = "[1, 1, 1]", cells = "[1, 1, 1]", box_upper = "[1, 1, 1]";
  cells.replace(static_cast<std::size_t>(1 + 3 * axis), 1, std::to_string(n));
  box_upper.replace(static_cast<std::size_t>(1 + 3 * axis), 1, "0.5");
  return gas_scene(upper, cells, "{material: gas, density: 0.125, pressure: 0.1}",
                   "bodies:\n  - {name: left, material: gas, density: 1.0, pressure: 1.0,\n"
                   "     shape: {box: {lower: [0, 0, 0], upper: " +
                       box_upper + "}}}\n");
}

}  // namespace mpfd::fdm::testing
