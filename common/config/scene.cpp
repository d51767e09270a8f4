#include "common/config/scene.hpp"

#include <algorithm>

namespace mpfd::config {

const Material* find_material(const Scene& scene, std::string_view name) {
  const auto it = std::find_if(scene.materials.begin(), scene.materials.end(),
                               [&](const Material& m) { return m.name == name; });
  return it == scene.materials.end() ? nullptr : &*it;
}

bool has_strength(const Material& material) {
  return !std::holds_alternative<NoStrength>(material.strength);
}

bool has_structure(const Scene& scene) {
  return std::any_of(scene.materials.begin(), scene.materials.end(),
                     [](const Material& m) { return has_strength(m); });
}

}  // namespace mpfd::config
