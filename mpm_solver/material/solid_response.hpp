#pragma once
// What every model with strength shares: the deviator, the von Mises stress,
// the energy equation (2-4) closed by the material's EOS, and the sound speed
// of a solid. The pressure stays the EOS's; strength only adds the deviator.

#include <cmath>
#include <variant>

#include "common/eos/any_eos.hpp"
#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/material/internal_energy_update.hpp"

namespace mpfd::mpm {

/// dev(t) = t - tr(t)/3 I.
[[nodiscard]] inline Tensor3 deviator(const Tensor3& t) noexcept {
  return t - (t.trace() / 3.0) * Tensor3::Identity();
}

/// Von Mises equivalent stress sqrt(3/2 s:s) [Pa] of a deviator s.
[[nodiscard]] inline double von_mises_stress(const Tensor3& s) noexcept {
  return std::sqrt(1.5 * s.squaredNorm());
}

/// s_avg : dev(Delta eps) [Pa], the deviatoric work term of (2-4), trapezoidal in s.
[[nodiscard]] inline double deviatoric_work(const Tensor3& s_old, const Tensor3& s_new,
                                            const Tensor3& deviatoric_increment) noexcept {
  return 0.5 * (s_old + s_new).cwiseProduct(deviatoric_increment).sum();
}

/// Advances e and p over the step by (2-4) with the given deviatoric work.
/// With no_tension (a failed material) a negative end pressure is replaced
/// by zero and the energy update uses that zero, so e and p stay consistent.
inline void advance_solid_energy(const eos::AnyEos& eos, const StrainStep& step,
                                 double deviatoric_work, bool no_tension, MaterialPoint& point) {
  std::visit(
      [&](const auto& model) {
        // Every EOS is affine in e at fixed rho (equation_of_state.hpp).
        const double offset = model.pressure(step.density_new, 0.0);
        const double slope = model.pressure(step.density_new, 1.0) - offset;
        EnergyStepInput in{point.specific_internal_energy, point.pressure, deviatoric_work, offset,
                           slope};
        EnergyStepResult next = advance_internal_energy(step, in);
        if (no_tension && next.pressure < 0.0) {
          in.pressure_offset_new = 0.0;
          in.pressure_slope_new = 0.0;
          next = advance_internal_energy(step, in);
        }
        point.specific_internal_energy = next.energy;
        point.pressure = next.pressure;
      },
      eos);
}

/// Longitudinal sound speed [m/s] of a solid: c^2 = (K + 4G/3) / rho, with
/// K / rho = c_EOS^2 from the EOS and shear modulus G [Pa].
[[nodiscard]] inline double solid_sound_speed(const eos::AnyEos& eos, double rho, double e,
                                              double shear_modulus) {
  const double bulk = eos::sound_speed(eos, rho, e);
  return std::sqrt(bulk * bulk + 4.0 * shear_modulus / (3.0 * rho));
}

}  // namespace mpfd::mpm
