#include "coupler/remap/shells_from_particles.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::remap {
namespace {

void require_count(std::size_t got, std::size_t want, const char* name) {
  if (got != want)
    throw Error(std::string("shells_from_particles: ") + name +
                " must have one value per particle (" + std::to_string(want) + "), got " +
                std::to_string(got));
}

void check_particles(const SphericalParticleView& p, double outer_radius) {
  const std::size_t n = p.radius.size();
  if (n == 0) throw Error("shells_from_particles: needs at least one particle, got none");
  require_count(p.mass_per_steradian.size(), n, "mass_per_steradian");
  require_count(p.velocity.size(), n, "velocity");
  require_count(p.specific_internal_energy.size(), n, "specific_internal_energy");
  require_count(p.material.size(), n, "material");
  if (!p.radial_stress.empty() || !p.hoop_stress.empty()) {
    require_count(p.radial_stress.size(), n, "radial_stress");
    require_count(p.hoop_stress.size(), n, "hoop_stress");
  }
  require(p.radius[0] >= 0.0, "shells_from_particles", "radius[0]", p.radius[0], ">= 0");
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0)
      require(p.radius[k] > p.radius[k - 1], "shells_from_particles",
              "radius[" + std::to_string(k) + "]", p.radius[k],
              "> radius[" + std::to_string(k - 1) + "] = " + shortest_text(p.radius[k - 1]));
    require(p.mass_per_steradian[k] >= 0.0, "shells_from_particles",
            "mass_per_steradian[" + std::to_string(k) + "]", p.mass_per_steradian[k], ">= 0");
  }
  require(outer_radius > p.radius[n - 1], "shells_from_particles", "outer_radius", outer_radius,
          "> the last particle's radius " + shortest_text(p.radius[n - 1]));
}

}  // namespace

RadialProfile RadialShells::view() const {
  return {edges, density, velocity, internal_energy, material, radial_stress, hoop_stress};
}

RadialShells shells_from_particles(const SphericalParticleView& particles, double outer_radius) {
  check_particles(particles, outer_radius);
  const std::size_t n = particles.radius.size();
  RadialShells shells;
  shells.edges.resize(n + 1);
  shells.edges[0] = 0.0;
  for (std::size_t k = 1; k < n; ++k)
    shells.edges[k] = 0.5 * (particles.radius[k - 1] + particles.radius[k]);
  shells.edges[n] = outer_radius;
  shells.density.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double r0 = shells.edges[k];
    const double r1 = shells.edges[k + 1];
    // The shell holds 4 pi m_k: rho (4 pi / 3)(r1^3 - r0^3) = 4 pi m_k.
    shells.density[k] = 3.0 * particles.mass_per_steradian[k] / (r1 * r1 * r1 - r0 * r0 * r0);
  }
  shells.velocity.assign(particles.velocity.begin(), particles.velocity.end());
  shells.internal_energy.assign(particles.specific_internal_energy.begin(),
                                particles.specific_internal_energy.end());
  shells.material.assign(particles.material.begin(), particles.material.end());
  shells.radial_stress.assign(particles.radial_stress.begin(), particles.radial_stress.end());
  shells.hoop_stress.assign(particles.hoop_stress.begin(), particles.hoop_stress.end());
  check_profile(shells.view());
  return shells;
}

SphericalTotals particle_totals(const SphericalParticleView& particles) {
  const std::size_t n = particles.mass_per_steradian.size();
  require_count(particles.velocity.size(), n, "velocity");
  require_count(particles.specific_internal_energy.size(), n, "specific_internal_energy");
  SphericalTotals t;
  constexpr double kSphere = 4.0 * std::numbers::pi;
  for (std::size_t k = 0; k < n; ++k) {
    const double m = kSphere * particles.mass_per_steradian[k];
    const double u = particles.velocity[k];
    t.mass += m;
    t.radial_impulse += m * u;
    t.radial_impulse_magnitude += std::abs(m * u);
    t.energy += m * (particles.specific_internal_energy[k] + 0.5 * u * u);
  }
  return t;
}

}  // namespace mpfd::coupler::remap
