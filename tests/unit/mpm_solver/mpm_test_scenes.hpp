#pragma once
// Small scenes for the MPM solver tests, written as scene files so that the
// tests go through the same parser as users.

#include <string>

#include "common/config/scene_loader.hpp"

namespace mpfd::mpm::testing {

/// A scene with an ideal gas (gamma 1.4) and any `extra` top-level YAML
/// (bodies, boundaries, solver): `upper` and `cells` as YAML lists.
inline config::Scene gas_scene(const std::string& upper, const std::string& cells,
                               const std::string& extra) {
  const std::string text =
      "name: test\ntime: {end: 1.0, cfl: 0.5}\n"
      "domain: {lower: [0, 0, 0], upper: " +
      upper + ", cells: " + cells +
      "}\nmaterials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: {material: gas, density: 1.0, pressure: 1.0}\n"
      "output: {interval: 1.0}\n" +
      extra;
  return config::parse_scene(text, "test.yaml");
}

/// A gas box body: lower/upper as YAML lists, with density, pressure and velocity.
inline std::string gas_body(const std::string& name, const std::string& lower,
                            const std::string& upper, double density, double pressure,
                            const std::string& velocity = "[0, 0, 0]", int per_axis = 2) {
  return "  - {name: " + name + ", material: gas, density: " + std::to_string(density) +
         ", pressure: " + std::to_string(pressure) + ", velocity: " + velocity +
         ", particles_per_axis: " + std::to_string(per_axis) +
         ",\n     shape: {box: {lower: " + lower + ", upper: " + upper + "}}}\n";
}

}  // namespace mpfd::mpm::testing
