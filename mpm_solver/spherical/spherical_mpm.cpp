#include "mpm_solver/spherical/spherical_mpm.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "common/core/error.hpp"
#include "mpm_solver/spherical/bulk_viscosity.hpp"
#include "mpm_solver/spherical/particle_seeding.hpp"

namespace mpfd::mpm::spherical {

SphericalMpm::SphericalMpm(std::vector<RadialLayer> layers, SphericalOptions options)
    : layers_(std::move(layers)), options_(options) {
  validate(layers_, options_);
  std::size_t stride = 0;
  for (const RadialLayer& layer : layers_) {
    models_.push_back(make_constitutive_model(layer.material));
    materials_.models.push_back(models_.back().get());
    materials_.detonation_velocity.push_back(
        layer.explosive ? layer.material.explosive->detonation_velocity : 0.0);
    stride = std::max(stride, static_cast<std::size_t>(models_.back()->history_count()));
  }
  settings_ = {options_.viscosity, options_.grid_spacing, options_.grid_spacing};
  seed_particles(layers_, options_, stride, particles_);

  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const auto m = static_cast<std::size_t>(particles_.material[p]);
    MaterialPoint point = particles_.point(p);
    models_[m]->initialise(particles_.density[p], point);
    if (particles_.burn_fraction[p] < 1.0) {
      // A still step at F(0) = 0 so the unburnt explosive's pressure is F p_JWL (T (3-1)).
      StrainStep still;
      still.dt = 1.0;
      still.density_old = still.density_new = particles_.density[p];
      still.burn_fraction = particles_.burn_fraction[p];
      models_[m]->update(still, point);
    }
  }
  ambient_pressure_ = particles_.pressure.back();
  if (options_.shape == RadialShape::linear &&
      options_.outer_boundary == OuterBoundary::transmitting && ambient_pressure_ != 0.0)
    throw Error("spherical MPM: a transmitting boundary holding an ambient pressure (" +
                std::to_string(ambient_pressure_) +
                " Pa) needs shape gimp; with linear shapes it is unstable (README)");
  const auto cells =
      static_cast<std::size_t>(std::lround(layers_.back().outer_radius / options_.grid_spacing));
  grid_.spacing = options_.grid_spacing;
  grid_.resize(cells + static_cast<std::size_t>(options_.margin_cells) + 2);
  weights_.resize(particles_.size());
}

void SphericalMpm::advance(double dt) {
  if (!(dt > 0.0)) throw Error("spherical MPM: dt must be > 0 s, got " + std::to_string(dt));
  scatter_to_grid(particles_, options_.shape, 0.5 / options_.particles_per_cell, grid_,
                  weights_);  // T (2-9), (2-12), S eq. (7)
  if (options_.outer_boundary == OuterBoundary::transmitting)
    add_transmitting_traction(particles_, ambient_pressure_, grid_);
  integrate_grid(grid_, dt);                                // T (2-13)
  update_particle_motion(particles_, grid_, weights_, dt);  // T (2-15), (2-16)
  remap_grid_velocity(particles_, weights_, grid_);         // T (2-17)
  time_ += dt;
  update_particle_stress(particles_, grid_, weights_, materials_, settings_, time_,
                         dt);  // S eq. (11), T (2-20), (2-21)
}

double SphericalMpm::stable_dt() const {
  const double h = options_.grid_spacing;
  double fastest = 0.0;
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const double c = particles_.sound_speed[p];
    const double q = viscous_speed(options_.viscosity, h, particles_.volumetric_rate[p], c);
    fastest = std::max(fastest, q + std::sqrt(q * q + c * c) + std::abs(particles_.velocity[p]));
  }
  if (!(fastest > 0.0)) return std::numeric_limits<double>::infinity();
  return options_.cfl * h / fastest;
}

void SphericalMpm::export_profile(RadialProfile& profile) const {
  const SphericalParticles& s = particles_;
  profile.radius = s.radius;
  profile.mass_per_steradian = s.mass;
  profile.velocity = s.velocity;
  profile.density = s.density;
  profile.pressure = s.pressure;
  profile.specific_internal_energy = s.specific_internal_energy;
  profile.burn_fraction = s.burn_fraction;
  profile.layer = s.material;
  profile.stress_rr.resize(s.size());
  profile.stress_hoop.resize(s.size());
  for (std::size_t p = 0; p < s.size(); ++p) {
    profile.stress_rr[p] = s.deviatoric_stress[p](0, 0) - s.pressure[p];
    profile.stress_hoop[p] = s.deviatoric_stress[p](1, 1) - s.pressure[p];
  }
}

double SphericalMpm::pressure_at(double radius) const {
  const std::vector<double>& r = particles_.radius;
  const auto above = std::lower_bound(r.begin(), r.end(), radius);
  if (above == r.begin()) return particles_.pressure.front();
  if (above == r.end()) return particles_.pressure.back();
  const auto j = static_cast<std::size_t>(above - r.begin());
  const double t = (radius - r[j - 1]) / (r[j] - r[j - 1]);
  return (1.0 - t) * particles_.pressure[j - 1] + t * particles_.pressure[j];
}

SphericalTotals SphericalMpm::totals() const {
  SphericalTotals sum;
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const double m = particles_.mass[p];
    sum.mass += m;
    sum.kinetic_energy += 0.5 * m * particles_.velocity[p] * particles_.velocity[p];
    sum.internal_energy += m * particles_.specific_internal_energy[p];
  }
  const double sphere = 4.0 * std::numbers::pi;
  return {sphere * sum.mass, sphere * sum.kinetic_energy, sphere * sum.internal_energy};
}

void SphericalMpm::restore(const SphericalParticles& particles, double time) {
  const std::size_t n = particles_.size();
  const auto refuse = [&](const std::string& what) {
    throw Error("spherical MPM: cannot restore " + what);
  };
  if (particles.size() != n)
    refuse(std::to_string(particles.size()) + " particles; this run seeds " + std::to_string(n));
  for (const auto& [name, field] : particles.scalar_fields())
    if (field->size() != n)
      refuse("'" + std::string(name) + "' of " + std::to_string(field->size()) +
             " values; expected one per particle, " + std::to_string(n));
  if (particles.history_stride != particles_.history_stride)
    refuse("a history of stride " + std::to_string(particles.history_stride) + "; expected " +
           std::to_string(particles_.history_stride) + " (this run's materials)");
  if (particles.history.size() != n * particles_.history_stride)
    refuse("a history of " + std::to_string(particles.history.size()) + " values; expected " +
           std::to_string(n * particles_.history_stride));
  if (particles.deviatoric_stress.size() != n)
    refuse(std::to_string(particles.deviatoric_stress.size()) + " stresses; expected " +
           std::to_string(n));
  if (particles.material.size() != n)
    refuse(std::to_string(particles.material.size()) + " materials; expected one per particle, " +
           std::to_string(n));
  const auto differs = std::mismatch(particles.material.begin(), particles.material.end(),
                                     particles_.material.begin());
  if (differs.first != particles.material.end())
    refuse("particles of other layers: particle " +
           std::to_string(differs.first - particles.material.begin()) + " has material " +
           std::to_string(*differs.first) + ", this run's seeding " +
           std::to_string(*differs.second));
  if (!(time >= 0.0) || !std::isfinite(time))
    refuse("at t = " + std::to_string(time) + " s; expected a finite time >= 0");
  particles_ = particles;
  time_ = time;
}

}  // namespace mpfd::mpm::spherical
