#include "mpm_solver/spherical/particle_seeding.hpp"

#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "mpm_solver/spherical/gauss_legendre.hpp"

namespace mpfd::mpm::spherical {
namespace {

/// The number of cells from r = 0 to radius, which must be a grid line.
std::size_t cells_to(double radius, double spacing, std::size_t layer) {
  const double cells = radius / spacing;
  const double whole = std::round(cells);
  if (whole < 1.0 || std::abs(cells - whole) > 1e-9 * std::max(1.0, whole))
    throw Error("spherical MPM: layer " + std::to_string(layer) + " outer radius " +
                std::to_string(radius) + " m must be a positive multiple of the grid spacing " +
                std::to_string(spacing) + " m");
  return static_cast<std::size_t>(whole);
}

}  // namespace

void validate(const std::vector<RadialLayer>& layers, const SphericalOptions& options) {
  if (!(options.grid_spacing > 0.0))
    throw Error("spherical MPM: grid_spacing must be > 0 m, got " +
                std::to_string(options.grid_spacing));
  if (options.particles_per_cell < 2)
    throw Error(
        "spherical MPM: particles_per_cell must be >= 2 (Gauss points that partition "
        "each shell), got " +
        std::to_string(options.particles_per_cell));
  if (!(options.cfl > 0.0 && options.cfl <= 1.0))
    throw Error("spherical MPM: cfl must be in (0, 1], got " + std::to_string(options.cfl));
  if (options.margin_cells < 1)
    throw Error("spherical MPM: margin_cells must be >= 1, got " +
                std::to_string(options.margin_cells));
  if (layers.empty()) throw Error("spherical MPM: expected at least one radial layer, got none");
  std::size_t previous = 0;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const RadialLayer& layer = layers[i];
    const std::size_t cells = cells_to(layer.outer_radius, options.grid_spacing, i);
    if (cells <= previous)
      throw Error("spherical MPM: layer " + std::to_string(i) + " ('" + layer.material.name +
                  "') outer radius " + std::to_string(layer.outer_radius) +
                  " m must exceed the previous layer's");
    previous = cells;
    if (!(layer.density > 0.0))
      throw Error("spherical MPM: layer " + std::to_string(i) + " ('" + layer.material.name +
                  "') density must be > 0 kg/m^3, got " + std::to_string(layer.density));
    if (layer.explosive && !layer.material.explosive)
      throw Error("spherical MPM: layer " + std::to_string(i) + " is explosive but material '" +
                  layer.material.name + "' has no explosive section (detonation velocity)");
  }
}

void seed_particles(const std::vector<RadialLayer>& layers, const SphericalOptions& options,
                    std::size_t history_stride, SphericalParticles& particles) {
  validate(layers, options);
  const double h = options.grid_spacing;
  const auto per_cell = static_cast<std::size_t>(options.particles_per_cell);
  const QuadratureRule rule = gauss_legendre(options.particles_per_cell);
  const std::size_t cells = cells_to(layers.back().outer_radius, h, layers.size() - 1);
  particles.resize(cells * per_cell, history_stride);

  std::size_t layer = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    const double centre = (static_cast<double>(c) + 0.5) * h;
    while (centre > layers[layer].outer_radius) ++layer;
    const RadialLayer& source = layers[layer];
    for (std::size_t j = 0; j < per_cell; ++j) {
      const std::size_t p = c * per_cell + j;
      double r = centre + 0.5 * h * rule.points[j];
      double volume = 0.5 * h * rule.weights[j] * r * r;  // = (r2^3 - r1^3)/3 of its shell
      if (options.shape == RadialShape::gimp) {
        // Equal sub-shells whose GIMP domains tile the cell.
        const double r1 =
            (static_cast<double>(c) + static_cast<double>(j) / static_cast<double>(per_cell)) * h;
        const double r2 = r1 + h / static_cast<double>(per_cell);
        r = 0.5 * (r1 + r2);
        volume = (r2 * r2 * r2 - r1 * r1 * r1) / 3.0;
      }
      particles.radius[p] = r;
      particles.density[p] = source.density;
      particles.mass[p] = source.density * volume;  // S eq. (1)
      particles.specific_internal_energy[p] = source.specific_internal_energy;
      particles.material[p] = static_cast<int>(layer);
      if (source.explosive) {
        particles.lighting_time[p] = r / source.material.explosive->detonation_velocity;  // T (3-2)
        particles.burn_fraction[p] = 0.0;
      } else {
        particles.burn_fraction[p] = 1.0;
      }
    }
  }
}

}  // namespace mpfd::mpm::spherical
