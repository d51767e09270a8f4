#include "mpm_solver/spherical/scene_layers.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "common/core/error.hpp"

namespace mpfd::mpm::spherical {
namespace {

/// One region of the scene as a candidate shell: a sphere about the centre
/// (radius), or the background (infinite radius).
struct Region {
  std::string name;
  double radius = 0.0;
  RadialLayer layer;  ///< everything but outer_radius
};

config::Material material_of(const config::Scene& scene, const std::string& name,
                             const std::string& where) {
  if (const config::Material* m = config::find_material(scene, name)) return *m;
  throw Error("scene '" + scene.name + "': " + where + ": no material named '" + name + "'");
}

RadialLayer state_layer(const config::Scene& scene, const config::MaterialState& s,
                        const std::string& where) {
  if (s.velocity != config::Vec3{0.0, 0.0, 0.0})
    throw Error("scene '" + scene.name + "': " + where +
                ": the 1D spherical MPM starts at rest; expected velocity [0, 0, 0]");
  RadialLayer layer;
  layer.material = material_of(scene, s.material, where);
  layer.density = s.density;
  layer.specific_internal_energy =
      s.specific_internal_energy ? *s.specific_internal_energy
                                 : eos::internal_energy(layer.material.eos, s.density, *s.pressure);
  if (!std::isfinite(layer.specific_internal_energy))
    throw Error("scene '" + scene.name + "': " + where + ": material '" + s.material +
                "' cannot reach the given pressure at density " + std::to_string(s.density));
  return layer;
}

RadialLayer charge_layer(const config::Scene& scene, const config::Charge& c) {
  const std::string where = "charge '" + c.name + "'";
  RadialLayer layer;
  layer.material = material_of(scene, c.material, where);
  const auto* jwl = std::get_if<eos::Jwl>(&layer.material.eos);
  if (!jwl || !layer.material.explosive)
    throw Error("scene '" + scene.name + "': " + where + ": material '" + c.material +
                "' must use the jwl EOS and have an explosive section");
  if (c.burn != config::Burn::program)
    throw Error("scene '" + scene.name + "': " + where +
                ": the 1D spherical MPM burns from the centre; expected burn: program");
  // Unreacted explosive at its reference state, as mpm_solver's 3D charges.
  layer.density = jwl->rho0;
  layer.specific_internal_energy = jwl->detonation_energy / jwl->rho0;
  layer.explosive = true;
  return layer;
}

double distance(const config::Vec3& a, const config::Vec3& b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

bool same_state(const config::MaterialState& a, const config::MaterialState& b) {
  return a.material == b.material && a.density == b.density && a.velocity == b.velocity &&
         a.pressure == b.pressure && a.specific_internal_energy == b.specific_internal_energy;
}

// The radius of `shape` as a shell about `centre`, or nothing if it stays
// outside outer_radius; throws if it reaches inside but is no such sphere.
std::optional<double> shell_radius(const config::Scene& scene, const config::Shape& shape,
                                   const std::string& where, const config::Vec3& centre,
                                   double outer_radius) {
  const config::Box box = config::bounding_box(shape);
  double gap = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double g = std::max({box.lower[i] - centre[i], 0.0, centre[i] - box.upper[i]});
    gap += g * g;
  }
  if (std::sqrt(gap) >= outer_radius) return std::nullopt;
  const auto* ball = std::get_if<config::Sphere>(&shape.kind);
  if (!ball || distance(ball->center, centre) != 0.0)
    throw Error("scene '" + scene.name + "': " + where +
                ": the 1D spherical MPM needs a sphere centred at [" + std::to_string(centre[0]) +
                ", " + std::to_string(centre[1]) + ", " + std::to_string(centre[2]) +
                "] within radius " + std::to_string(outer_radius) + " m");
  return ball->radius;
}

}  // namespace

std::vector<RadialLayer> layers_from_scene(const config::Scene& scene, const config::Vec3& centre,
                                           double outer_radius) {
  if (!(outer_radius > 0.0))
    throw Error("scene '" + scene.name + "': the 1D line needs an outer radius > 0 m, got " +
                std::to_string(outer_radius));
  std::vector<Region> regions;  // later ones overwrite earlier ones
  for (const config::Body& b : scene.bodies) {
    const std::string where = "body '" + b.name + "'";
    if (same_state(b.state, scene.initial)) continue;  // background, whatever its shape
    if (const auto r = shell_radius(scene, b.shape, where, centre, outer_radius))
      regions.push_back({b.name, *r, state_layer(scene, b.state, where)});
  }
  for (const config::Charge& c : scene.charges) {
    const std::string where = "charge '" + c.name + "'";
    if (const auto r = shell_radius(scene, c.shape, where, centre, outer_radius))
      regions.push_back({c.name, *r, charge_layer(scene, c)});
  }
  std::vector<double> edges{outer_radius};
  for (const Region& r : regions)
    if (r.radius < outer_radius) edges.push_back(r.radius);
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  const RadialLayer background = state_layer(scene, scene.initial, "initial");
  std::vector<RadialLayer> layers;
  std::ptrdiff_t previous = -2;  // index into regions of the last layer, -1 = background
  for (const double edge : edges) {
    std::ptrdiff_t source = -1;
    for (std::size_t i = 0; i < regions.size(); ++i)
      if (regions[i].radius >= edge) source = static_cast<std::ptrdiff_t>(i);
    if (source == previous) {
      layers.back().outer_radius = edge;
      continue;
    }
    layers.push_back(source < 0 ? background : regions[static_cast<std::size_t>(source)].layer);
    layers.back().outer_radius = edge;
    previous = source;
  }
  return layers;
}

std::vector<RadialLayer> layers_from_scene(const config::Scene& scene) {
  return layers_from_scene(scene, {0.0, 0.0, 0.0}, scene.domain.upper[0]);
}

namespace {

RadialShape radial_shape(const config::Scene& scene, config::ShapeFunction shape,
                         const std::string& key) {
  switch (shape) {
    case config::ShapeFunction::linear:
      return RadialShape::linear;
    case config::ShapeFunction::gimp:
      return RadialShape::gimp;
    case config::ShapeFunction::cpgimp:
      break;
  }
  throw Error("scene '" + scene.name + "': " + key +
              ": the 1D spherical MPM has linear and gimp shapes; got cpgimp");
}

int particles_per_cell(const config::Scene& scene) {
  if (!scene.charges.empty()) return scene.charges.front().particles_per_axis;
  if (!scene.bodies.empty()) return scene.bodies.front().particles_per_axis;
  return SphericalOptions{}.particles_per_cell;
}

}  // namespace

SphericalOptions options_from_scene(const config::Scene& scene) {
  SphericalOptions o;
  o.viscosity = {scene.solver.mpm.bulk_viscosity_quadratic, scene.solver.mpm.bulk_viscosity_linear};
  const config::Domain& d = scene.domain;
  if (d.geometry == config::Geometry::spherical) {
    o.grid_spacing = (d.upper[0] - d.lower[0]) / d.cells[0];
    o.particles_per_cell = particles_per_cell(scene);
    o.cfl = scene.time.mpm_cfl();
    o.shape = radial_shape(scene, scene.solver.mpm.shape_function, "solver.mpm.shape_function");
    const config::BoundaryKind outer = scene.boundaries[config::Face::x_upper];
    if (outer == config::BoundaryKind::non_reflecting)
      o.outer_boundary = OuterBoundary::transmitting;
    else if (outer == config::BoundaryKind::outflow)
      o.outer_boundary = OuterBoundary::free;
    else
      throw Error("scene '" + scene.name +
                  "': boundaries.x_upper: the 1D spherical MPM's outer surface is outflow "
                  "(free) or non_reflecting (transmitting)");
    return o;
  }
  const config::AfdmpSpherical& a = scene.solver.afdmp.spherical;
  double smallest = (d.upper[0] - d.lower[0]) / d.cells[0];
  for (int i = 1; i < 3; ++i) smallest = std::min(smallest, (d.upper[i] - d.lower[i]) / d.cells[i]);
  o.grid_spacing = a.grid_spacing.value_or(smallest / 4.0);
  o.particles_per_cell = a.particles_per_cell;
  o.cfl = a.cfl;
  o.shape = radial_shape(scene, a.shape_function, "solver.afdmp.spherical.shape_function");
  o.outer_boundary = OuterBoundary::transmitting;
  return o;
}

}  // namespace mpfd::mpm::spherical
