#include "coupler/run/injected_material.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

std::uint32_t index_of(const config::Scene& scene, const std::string& name) {
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return static_cast<std::uint32_t>(i);
  throw Error("scene '" + scene.name + "': no material '" + name + "'");
}

}  // namespace

InjectedMaterial::InjectedMaterial(const config::Scene& scene) : scene_(scene) {
  fluids_.push_back(index_of(scene, scene.initial.material));
  for (const auto& body : scene.bodies) {
    const std::uint32_t m = index_of(scene, body.state.material);
    if (!config::has_strength(scene.materials[m]) &&
        std::find(fluids_.begin(), fluids_.end(), m) == fluids_.end())
      fluids_.push_back(m);
  }
}

std::uint32_t InjectedMaterial::choose(double rho, double e, double p) const {
  std::uint32_t best = fluids_.front();
  double best_gap = std::numeric_limits<double>::infinity();
  for (const std::uint32_t m : fluids_) {
    const double gap = std::abs(eos::pressure(scene_.materials[m].eos, rho, e) - p);
    if (gap < best_gap) {  // ties keep the earlier one: initial.material first
      best_gap = gap;
      best = m;
    }
  }
  return best;
}

}  // namespace mpfd::coupler
