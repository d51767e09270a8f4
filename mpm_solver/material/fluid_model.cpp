#include "mpm_solver/material/fluid_model.hpp"

#include <algorithm>

#include "mpm_solver/material/internal_energy_update.hpp"

namespace mpfd::mpm {

void FluidModel::initialise(double rho, MaterialPoint& point) const {
  point.deviatoric_stress.setZero();
  point.pressure = eos::pressure(eos_, rho, point.specific_internal_energy);
  point.sound_speed = eos::sound_speed(eos_, rho, point.specific_internal_energy);
}

void FluidModel::update(const StrainStep& step, MaterialPoint& point) const {
  const double burn = std::clamp(step.burn_fraction, 0.0, 1.0);
  std::visit(
      [&](const auto& eos) {
        // Every EOS is affine in e at fixed rho (equation_of_state.hpp).
        const double offset = eos.pressure(step.density_new, 0.0);
        const double slope = eos.pressure(step.density_new, 1.0) - offset;
        const EnergyStepResult next = advance_internal_energy(
            step,
            {point.specific_internal_energy, point.pressure, 0.0, burn * offset, burn * slope});
        point.specific_internal_energy = next.energy;
        point.pressure = next.pressure;
        // An unburnt particle still carries sound at the products' speed, so
        // the stable step does not jump when the front arrives.
        point.sound_speed = eos.sound_speed(step.density_new, next.energy);
      },
      eos_);
  point.deviatoric_stress.setZero();
}

}  // namespace mpfd::mpm
