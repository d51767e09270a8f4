#include "coupler/run/spherical_stage.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"
#include "mpm_solver/spherical/scene_layers.hpp"

namespace mpfd::coupler {
namespace {

namespace sph = mpm::spherical;

grid::Vec3 charge_centre(const config::Scene& scene) {
  if (scene.charges.size() != 1 ||
      !std::holds_alternative<config::Sphere>(scene.charges[0].shape.kind))
    throw Error("scene '" + scene.name +
                "': solver.afdmp.start: spherical needs exactly one charge, a sphere");
  return std::get<config::Sphere>(scene.charges[0].shape.kind).center;
}

double handoff_radius(const config::Scene& scene) {
  const auto& radius = scene.solver.afdmp.spherical.handoff_radius;
  if (!radius || *radius <= 0)
    throw Error("scene '" + scene.name +
                "': solver.afdmp.spherical.handoff_radius must be > 0 [m] with start: spherical");
  return *radius;
}

/// kReachFactor x handoff_radius, rounded down to the 1D grid (layers end on grid
/// lines; the scene check cleared the ball of kReachFactor x handoff_radius).
double stage_radius(const config::Scene& scene) {
  const double h = sph::options_from_scene(scene).grid_spacing;
  const double radius = handoff_radius(scene);
  const double reach = h * std::floor(kReachFactor * radius / h + 1e-9);
  if (reach < radius + h)
    throw Error(
        "scene '" + scene.name + "': solver.afdmp.spherical.grid_spacing " + std::to_string(h) +
        " m leaves the 1D stage no room beyond handoff_radius " + std::to_string(radius) +
        " m; expected grid_spacing <= " + std::to_string((kReachFactor - 1) * radius / 2) + " m");
  return reach;
}

}  // namespace

SphericalStage::SphericalStage(const config::Scene& scene)
    : scene_(scene),
      centre_(charge_centre(scene)),
      mpm_(sph::layers_from_scene(scene, centre_, stage_radius(scene)),
           sph::options_from_scene(scene)) {
  for (const auto& layer : mpm_.layers()) {
    const config::Material* m = config::find_material(scene, layer.material.name);
    if (m == nullptr)
      throw Error("scene '" + scene.name + "': no material '" + layer.material.name + "'");
    layer_material_.push_back(static_cast<int>(m - scene.materials.data()));
  }
  ambient_pressure_ = mpm_.particles().pressure.back();
}

bool SphericalStage::burn_complete() const {
  const auto& burn = mpm_.particles().burn_fraction;
  return std::all_of(burn.begin(), burn.end(), [](double f) { return f >= 1.0; });
}

double SphericalStage::front_radius() const {
  const auto& ps = mpm_.particles();
  const double threshold = ambient_pressure_ + scene_.solver.afdmp.spherical.front_overpressure;
  for (std::size_t p = ps.size(); p-- > 0;)
    if (ps.pressure[p] >= threshold) return ps.radius[p];
  return 0.0;
}

void SphericalStage::gauge_pressures(std::span<double> out) const {
  for (std::size_t g = 0; g < scene_.gauges.size(); ++g) {
    const auto& x = scene_.gauges[g].position;
    out[g] = mpm_.pressure_at(std::hypot(x[0] - centre_[0], x[1] - centre_[1], x[2] - centre_[2]));
  }
}

remap::RadialShells SphericalStage::shells() const {
  sph::RadialProfile profile;
  mpm_.export_profile(profile);
  std::vector<int> material(profile.layer.size());
  for (std::size_t p = 0; p < material.size(); ++p)
    material[p] = layer_material_.at(static_cast<std::size_t>(profile.layer[p]));
  const std::size_t n = profile.radius.size();
  // The last particle's shell ends half a particle spacing beyond it.
  const double outer =
      n > 1 ? profile.radius[n - 1] + 0.5 * (profile.radius[n - 1] - profile.radius[n - 2])
            : 2 * profile.radius[0];
  return remap::shells_from_particles({.radius = profile.radius,
                                       .mass_per_steradian = profile.mass_per_steradian,
                                       .velocity = profile.velocity,
                                       .specific_internal_energy = profile.specific_internal_energy,
                                       .material = material,
                                       .radial_stress = {},
                                       .hoop_stress = {}},
                                      outer);
}

}  // namespace mpfd::coupler
