#include "mpm_solver/material/johnson_cook_model.hpp"

#include "common/core/error.hpp"
#include "mpm_solver/material/radial_return.hpp"
#include "mpm_solver/material/solid_response.hpp"

namespace mpfd::mpm {

JohnsonCookModel::JohnsonCookModel(eos::AnyEos eos, const config::JohnsonCook& parameters)
    : eos_(eos),
      parameters_(parameters),
      flow_stress_(parameters),
      name_("johnson_cook+" + std::string(eos::name(eos))) {}

void JohnsonCookModel::initialise(double rho, MaterialPoint& point) const {
  MPFD_ASSERT(point.history.size() >= 1, "a Johnson-Cook point keeps its plastic strain rate");
  point.deviatoric_stress.setZero();
  point.temperature = parameters_.room_temperature;
  point.history[kPlasticStrainRate] = 0.0;
  point.pressure = eos::pressure(eos_, rho, point.specific_internal_energy);
  point.sound_speed =
      solid_sound_speed(eos_, rho, point.specific_internal_energy, parameters_.shear_modulus);
}

void JohnsonCookModel::update(const StrainStep& step, MaterialPoint& point) const {
  const double g = parameters_.shear_modulus;
  const Tensor3 increment = deviator(step.strain_increment);
  const Tensor3 s_old = point.deviatoric_stress;
  double plastic_increment = 0.0;
  if (point.damage >= 1.0) {
    point.deviatoric_stress.setZero();
  } else {
    const Tensor3 trial = s_old + 2.0 * g * increment;  // T (2-21), elastic trial
    const double q_trial = von_mises_stress(trial);
    const double thermal = flow_stress_.thermal_factor(point.temperature);
    const double eps_p = point.equivalent_plastic_strain;
    const auto flow = [&](double x) {
      return flow_stress_.after_increment(eps_p, x, step.dt, thermal);
    };
    point.deviatoric_stress = trial;
    if (q_trial > flow(0.0).value) {
      plastic_increment = plastic_strain_increment(q_trial, 3.0 * g, flow);
      const double yield = flow(plastic_increment).value;
      // Scaling by sigma_y / q_trial puts s on the yield surface to round-off
      // whatever the solver's last residual.
      point.deviatoric_stress *= yield / q_trial;
      const double v_avg = 0.5 * (1.0 / step.density_old + 1.0 / step.density_new);
      const double work = yield * plastic_increment * v_avg;
      point.plastic_work += work;
      point.temperature += kTaylorQuinney * work / parameters_.specific_heat;
      point.equivalent_plastic_strain += plastic_increment;
    }
    if (parameters_.failure_strain &&
        point.equivalent_plastic_strain >= *parameters_.failure_strain) {
      point.damage = 1.0;
      point.deviatoric_stress.setZero();
    }
  }
  point.history[kPlasticStrainRate] = step.dt > 0.0 ? plastic_increment / step.dt : 0.0;
  const bool failed = point.damage >= 1.0;
  advance_solid_energy(eos_, step, deviatoric_work(s_old, point.deviatoric_stress, increment),
                       failed, point);
  point.sound_speed =
      solid_sound_speed(eos_, step.density_new, point.specific_internal_energy, failed ? 0.0 : g);
}

}  // namespace mpfd::mpm
