#include "mpm_solver/spherical/spherical_particles.hpp"

namespace mpfd::mpm::spherical {

void SphericalParticles::resize(std::size_t n, std::size_t stride) {
  for (auto* f : {&radius, &velocity, &mass, &density, &pressure, &bulk_viscosity, &volumetric_rate,
                  &specific_internal_energy, &sound_speed, &equivalent_plastic_strain,
                  &plastic_work, &damage, &temperature, &lighting_time, &burn_fraction})
    f->assign(n, 0.0);
  deviatoric_stress.assign(n, Tensor3::Zero());
  material.assign(n, 0);
  history_stride = stride;
  history.assign(n * stride, 0.0);
}

MaterialPoint SphericalParticles::point(std::size_t p) {
  return {deviatoric_stress[p],
          pressure[p],
          specific_internal_energy[p],
          sound_speed[p],
          equivalent_plastic_strain[p],
          plastic_work[p],
          damage[p],
          temperature[p],
          std::span<double>(history.data() + p * history_stride, history_stride)};
}

}  // namespace mpfd::mpm::spherical
