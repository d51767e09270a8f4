#include "mpm_solver/material/elastic_model.hpp"

#include "mpm_solver/material/solid_response.hpp"

namespace mpfd::mpm {

ElasticModel::ElasticModel(eos::AnyEos eos, double shear_modulus)
    : eos_(eos), shear_modulus_(shear_modulus), name_("elastic+" + std::string(eos::name(eos))) {}

void ElasticModel::initialise(double rho, MaterialPoint& point) const {
  point.deviatoric_stress.setZero();
  point.pressure = eos::pressure(eos_, rho, point.specific_internal_energy);
  point.sound_speed = solid_sound_speed(eos_, rho, point.specific_internal_energy, shear_modulus_);
}

void ElasticModel::update(const StrainStep& step, MaterialPoint& point) const {
  const Tensor3 increment = deviator(step.strain_increment);
  const Tensor3 s_old = point.deviatoric_stress;
  point.deviatoric_stress = s_old + 2.0 * shear_modulus_ * increment;  // T (2-21)
  advance_solid_energy(eos_, step, deviatoric_work(s_old, point.deviatoric_stress, increment),
                       false, point);
  point.sound_speed =
      solid_sound_speed(eos_, step.density_new, point.specific_internal_energy, shear_modulus_);
}

}  // namespace mpfd::mpm
