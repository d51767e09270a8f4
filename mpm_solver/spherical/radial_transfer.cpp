#include "mpm_solver/spherical/radial_transfer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"

namespace mpfd::mpm::spherical {

void scatter_to_grid(const SphericalParticles& particles, RadialShape shape,
                     double half_width_cells, RadialGrid& grid, ParticleWeights& weights) {
  std::fill(grid.mass.begin(), grid.mass.end(), 0.0);
  std::fill(grid.momentum.begin(), grid.momentum.end(), 0.0);
  std::fill(grid.force.begin(), grid.force.end(), 0.0);
  std::fill(grid.dashpot.begin(), grid.dashpot.end(), 0.0);
  const double inverse_h = 1.0 / grid.spacing;
  // Serial: neighbouring particles share nodes, and a 1D run is small.
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double r = particles.radius[p];
    const RadialWeights w = shape == RadialShape::gimp
                                ? gimp_weights(r, grid.spacing, half_width_cells * grid.spacing)
                                : linear_weights(r, inverse_h);
    weights[p] = w;
    const double m = particles.mass[p];
    const double volume = m / particles.density[p];
    const double sigma_rr = particles.stress_rr(p);
    const double sigma_hoop = particles.stress_hoop(p);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t i = w.first + k;
      grid.mass[i] += w.value[k] * m;                              // T (2-12)
      grid.momentum[i] += w.value[k] * m * particles.velocity[p];  // T (2-9)
      grid.force[i] -=
          volume * (sigma_rr * w.gradient[k] + 2.0 * sigma_hoop * w.hoop[k]);  // S eq. (7)
    }
  }
}

void add_transmitting_traction(const SphericalParticles& particles, double ambient_pressure,
                               RadialGrid& grid) {
  // r_s = r + t/2 for the outermost particle at the middle of its shell of
  // volume V = m / rho: (r + t/2)^3 - (r - t/2)^3 = 3V, i.e. t (r^2 + t^2/12) = V.
  const std::size_t last = particles.size() - 1;
  const double r = particles.radius[last];
  const double volume = particles.mass[last] / particles.density[last];
  double thickness = volume / (r * r);
  for (int iteration = 0; iteration < 3; ++iteration)
    thickness = volume / (r * r + thickness * thickness / 12.0);
  const double surface = std::min(r + 0.5 * thickness, grid.outer_radius() - grid.spacing);
  const double area = surface * surface;  // per unit solid angle
  const double impedance = particles.density[last] * particles.sound_speed[last];
  // Applied at r_s itself, where the internal force of a uniform state ends.
  const RadialWeights at_surface = linear_weights(surface, 1.0 / grid.spacing);
  for (std::size_t k = 0; k < 2; ++k) {
    grid.force[at_surface.first + k] -= at_surface.value[k] * ambient_pressure * area;
    grid.dashpot[at_surface.first + k] += at_surface.value[k] * impedance * area;
  }
}

void integrate_grid(RadialGrid& grid, double dt) {
  grid.momentum[0] = 0.0;  // centre: v = 0 by symmetry
  grid.force[0] = 0.0;
  for (std::size_t i = 1; i < grid.size(); ++i) {
    // (2-13) with the dashpot taken at v^{n+1}: stable for any impedance.
    const double damping = grid.mass[i] > 0.0 ? grid.dashpot[i] * dt / grid.mass[i] : 0.0;
    const double momentum_new = (grid.momentum[i] + grid.force[i] * dt) / (1.0 + damping);
    grid.force[i] = (momentum_new - grid.momentum[i]) / dt;  // f_I including the dashpot, (2-14)
    grid.momentum[i] = momentum_new;
  }
}

void update_particle_motion(SphericalParticles& particles, const RadialGrid& grid,
                            const ParticleWeights& weights, double dt) {
  const auto node_ratio = [&](const std::vector<double>& field, std::size_t i) {
    return grid.mass[i] > 0.0 ? field[i] / grid.mass[i] : 0.0;
  };
  // The last two nodes stay empty, so every stencil fits in the grid.
  const double limit = grid.outer_radius() - grid.spacing;
  const std::size_t escaped = parallel_sum(particles.size(), [&](std::size_t p) -> std::size_t {
    const RadialWeights& w = weights[p];
    double acceleration = 0.0;
    double velocity = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      acceleration += w.value[k] * node_ratio(grid.force, w.first + k);
      velocity += w.value[k] * node_ratio(grid.momentum, w.first + k);
    }
    particles.velocity[p] += acceleration * dt;  // T (2-15)
    particles.radius[p] += velocity * dt;        // T (2-16)
    return particles.radius[p] < limit ? 0 : 1;  // also catches a NaN radius
  });
  if (escaped > 0)
    throw Error("spherical MPM: " + std::to_string(escaped) + " particle(s) moved beyond radius " +
                std::to_string(limit) +
                " m, one cell inside the grid; expected margin_cells to hold them");
}

void remap_grid_velocity(const SphericalParticles& particles, const ParticleWeights& weights,
                         RadialGrid& grid) {
  std::fill(grid.velocity.begin(), grid.velocity.end(), 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const RadialWeights& w = weights[p];
    const double mv = particles.mass[p] * particles.velocity[p];
    for (std::size_t k = 0; k < 3; ++k) grid.velocity[w.first + k] += w.value[k] * mv;
  }
  grid.velocity[0] = 0.0;
  for (std::size_t i = 1; i < grid.size(); ++i)
    grid.velocity[i] = grid.mass[i] > 0.0 ? grid.velocity[i] / grid.mass[i] : 0.0;  // (2-17)
}

}  // namespace mpfd::mpm::spherical
