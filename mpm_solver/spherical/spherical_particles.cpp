#include "mpm_solver/spherical/spherical_particles.hpp"

namespace mpfd::mpm::spherical {
namespace {

template <class Field, class Particles>
SphericalParticles::NamedFields<Field> scalar_fields_of(Particles& s) {
  return {{{"radius", &s.radius},
           {"velocity", &s.velocity},
           {"mass", &s.mass},
           {"density", &s.density},
           {"pressure", &s.pressure},
           {"bulk_viscosity", &s.bulk_viscosity},
           {"volumetric_rate", &s.volumetric_rate},
           {"specific_internal_energy", &s.specific_internal_energy},
           {"sound_speed", &s.sound_speed},
           {"equivalent_plastic_strain", &s.equivalent_plastic_strain},
           {"plastic_work", &s.plastic_work},
           {"damage", &s.damage},
           {"temperature", &s.temperature},
           {"lighting_time", &s.lighting_time},
           {"burn_fraction", &s.burn_fraction}}};
}

}  // namespace

SphericalParticles::NamedFields<std::vector<double>> SphericalParticles::scalar_fields() {
  return scalar_fields_of<std::vector<double>>(*this);
}

SphericalParticles::NamedFields<const std::vector<double>> SphericalParticles::scalar_fields()
    const {
  return scalar_fields_of<const std::vector<double>>(*this);
}

void SphericalParticles::resize(std::size_t n, std::size_t stride) {
  for (const auto& [name, field] : scalar_fields()) field->assign(n, 0.0);
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
