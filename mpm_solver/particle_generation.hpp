#pragma once
// Material points from a scene's bodies and charges: particles_per_axis
// points per cell along each active axis, at the centres of the equal
// sub-cells (so every point carries cell volume / n^d), kept where the shape
// holds them. A later body or charge owns its region: a point of an earlier
// one that lies inside a later shape is dropped (the same precedence as the
// FDM cells, common/initial). The background `initial` state is not filled
// with particles: in pure MPM the space around the bodies is empty; a scene
// that wants air around a charge describes it as a body (docs/mpm.md).

#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"
#include "mpm_solver/particle_set.hpp"

namespace mpfd::mpm {

/// What the step needs to know about a body or charge its particles came from.
struct BodyInfo {
  std::string name;
  std::size_t material = 0;          ///< index into Scene::materials
  int particles_per_axis = 2;        ///< along each active axis
  grid::Vec3 half_width{};           ///< GIMP particle half-width per axis [grid units]
  double characteristic_length = 0;  ///< h of the program burn T (3-2): particle spacing [m]
  double burn_rate = 0.0;            ///< D / (1.5 h) [1/s]; 0 for inert bodies
};

struct GeneratedParticles {
  ParticleSet particles;  ///< position, velocity, mass, density, e, material, body, lighting time
  std::vector<BodyInfo> bodies;  ///< scene bodies in file order, then charges
};

/// Throws mpfd::Error naming the body if a state is unphysical, a charge's
/// material is not JWL with an explosive section, or a body gets no particle.
[[nodiscard]] GeneratedParticles generate_particles(const config::Scene& scene,
                                                    const grid::UniformGrid& grid);

}  // namespace mpfd::mpm
