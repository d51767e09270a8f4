#include "mpm_solver/spherical/radial_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"

namespace mpfd::mpm::spherical {

void scatter_to_grid(const SphericalParticles& particles, RadialGrid& grid,
                     ParticleWeights& weights) {
  std::fill(grid.mass.begin(), grid.mass.end(), 0.0);
  std::fill(grid.momentum.begin(), grid.momentum.end(), 0.0);
  std::fill(grid.force.begin(), grid.force.end(), 0.0);
  const double inverse_h = 1.0 / grid.spacing;
  // Serial: neighbouring particles share nodes, and a 1D run is small.
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const RadialWeights w = radial_weights(particles.radius[p], inverse_h);
    weights[p] = w;
    const std::size_t c = w.cell;
    const double m = particles.mass[p];
    grid.mass[c] += w.left * m;  // T (2-12)
    grid.mass[c + 1] += w.right * m;
    grid.momentum[c] += w.left * m * particles.velocity[p];  // T (2-9)
    grid.momentum[c + 1] += w.right * m * particles.velocity[p];
    const double volume = m / particles.density[p];
    const double radial = particles.stress_rr(p) * inverse_h;
    const double hoop = 2.0 * particles.stress_hoop(p) / particles.radius[p];
    grid.force[c] -= volume * (-radial + hoop * w.left);  // S eq. (7), rebuilt
    grid.force[c + 1] -= volume * (radial + hoop * w.right);
  }
}

void add_transmitting_traction(const SphericalParticles& particles,
                               const ParticleWeights& weights, RadialGrid& grid) {
  double volume = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    volume += particles.mass[p] / particles.density[p];
  const double surface = std::cbrt(3.0 * volume);
  const std::size_t last = particles.size() - 1;
  const double traction =
      -particles.density[last] * particles.sound_speed[last] * particles.velocity[last];
  const double force = traction * surface * surface;  // per unit solid angle
  grid.force[weights[last].cell] += weights[last].left * force;
  grid.force[weights[last].cell + 1] += weights[last].right * force;
}

void integrate_grid(RadialGrid& grid, double dt) {
  grid.momentum[0] = 0.0;  // centre: v = 0 by symmetry
  grid.force[0] = 0.0;
  for (std::size_t i = 1; i < grid.size(); ++i) grid.momentum[i] += grid.force[i] * dt;  // (2-13)
}

void update_particle_motion(SphericalParticles& particles, const RadialGrid& grid,
                            const ParticleWeights& weights, double dt) {
  const auto node_ratio = [&](const std::vector<double>& field, std::size_t i) {
    return grid.mass[i] > 0.0 ? field[i] / grid.mass[i] : 0.0;
  };
  const std::size_t escaped = parallel_sum(particles.size(), [&](std::size_t p) -> std::size_t {
    const RadialWeights& w = weights[p];
    const std::size_t c = w.cell;
    particles.velocity[p] +=
        (w.left * node_ratio(grid.force, c) + w.right * node_ratio(grid.force, c + 1)) *
        dt;  // T (2-15)
    particles.radius[p] +=
        (w.left * node_ratio(grid.momentum, c) + w.right * node_ratio(grid.momentum, c + 1)) *
        dt;  // T (2-16)
    return particles.radius[p] >= grid.outer_radius() ? 1 : 0;
  });
  if (escaped > 0)
    throw Error("spherical MPM: " + std::to_string(escaped) +
                " particle(s) moved beyond the grid's outer radius " +
                std::to_string(grid.outer_radius()) + " m; expected margin_cells to hold them");
}

void remap_grid_velocity(const SphericalParticles& particles, const ParticleWeights& weights,
                         RadialGrid& grid) {
  std::fill(grid.velocity.begin(), grid.velocity.end(), 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const RadialWeights& w = weights[p];
    const double mv = particles.mass[p] * particles.velocity[p];
    grid.velocity[w.cell] += w.left * mv;
    grid.velocity[w.cell + 1] += w.right * mv;
  }
  grid.velocity[0] = 0.0;
  for (std::size_t i = 1; i < grid.size(); ++i)
    grid.velocity[i] = grid.mass[i] > 0.0 ? grid.velocity[i] / grid.mass[i] : 0.0;  // (2-17)
}

}  // namespace mpfd::mpm::spherical
