#include "mpm_solver/spherical/particle_stress_update.hpp"

#include "common/core/parallel_for.hpp"
#include "mpm_solver/spherical/bulk_viscosity.hpp"
#include "mpm_solver/spherical/program_burn.hpp"

namespace mpfd::mpm::spherical {

void update_particle_stress(SphericalParticles& particles, const RadialGrid& grid,
                            const ParticleWeights& weights, const MaterialTable& materials,
                            const StressUpdateSettings& settings, double time_new, double dt) {
  parallel_for(particles.size(), [&](std::size_t p) {
    const RadialWeights& w = weights[p];
    double radial = 0.0;
    double hoop = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      radial += w.gradient[k] * grid.velocity[w.first + k] * dt;  // S eq. (11)
      hoop += w.hoop[k] * grid.velocity[w.first + k] * dt;        // S eq. (11): v / r at r_p^n
    }
    const double volumetric = radial + 2.0 * hoop;

    StrainStep step;
    step.strain_increment.diagonal() << radial, hoop, hoop;
    step.dt = dt;
    step.density_old = particles.density[p];
    step.density_new = particles.density[p] / (1.0 + volumetric);  // T (2-20)
    const double rate = volumetric / dt;
    step.bulk_viscosity =
        bulk_viscosity(settings.viscosity, step.density_new, settings.viscous_length, rate,
                       particles.sound_speed[p]);  // S eq. (16)
    const auto m = static_cast<std::size_t>(particles.material[p]);
    if (materials.detonation_velocity[m] > 0.0)
      particles.burn_fraction[p] =
          burn_fraction(time_new, particles.lighting_time[p], materials.detonation_velocity[m],
                        settings.particle_length);  // T (3-2)
    step.burn_fraction = particles.burn_fraction[p];

    MaterialPoint point = particles.point(p);
    materials.models[m]->update(step, point);
    particles.density[p] = step.density_new;
    particles.bulk_viscosity[p] = step.bulk_viscosity;
    particles.volumetric_rate[p] = rate;
  });
}

}  // namespace mpfd::mpm::spherical
