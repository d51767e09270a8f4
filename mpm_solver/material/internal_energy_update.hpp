#pragma once
// The energy equation (2-4) over one step, per unit mass:
//   e^{n+1} = e^n + s_avg : dev(Delta eps) v_avg - (p_avg + q) Delta v
// with trapezoidal averages of s, p and the specific volume v = 1/rho, and
// Delta v = tr(Delta eps) / rho^n, the exact volume change of (2-20). The step's q is already the
// end-of-step value. p^{n+1} depends on e^{n+1}; every EOS in common/ is affine in e at fixed rho
// (p = p_ref + k e, equation_of_state.hpp), so the implicit trapezoid is solved in closed form
// rather than iterated.

#include "mpm_solver/material/constitutive_model.hpp"

namespace mpfd::mpm {

/// What the energy update needs besides the strain step.
struct EnergyStepInput {
  double energy_old = 0.0;           ///< e^n [J/kg]
  double pressure_old = 0.0;         ///< p^n [Pa], as used for stress (times F)
  double deviatoric_work = 0.0;      ///< s_avg : dev(Delta eps) [Pa]
  double pressure_offset_new = 0.0;  ///< F p_ref(rho^{n+1}) [Pa]
  double pressure_slope_new = 0.0;   ///< F k(rho^{n+1}) = F (dp/de)_rho [kg/m^3]
};

struct EnergyStepResult {
  double energy = 0.0;    ///< e^{n+1} [J/kg]
  double pressure = 0.0;  ///< p^{n+1} [Pa]
};

/// Trapezoidal (2-4) with p^{n+1} = offset + slope e^{n+1}, solved exactly.
[[nodiscard]] inline EnergyStepResult advance_internal_energy(const StrainStep& step,
                                                              const EnergyStepInput& in) noexcept {
  const double dv = step.strain_increment.trace() / step.density_old;
  const double v_avg = 0.5 * (1.0 / step.density_old + 1.0 / step.density_new);
  // e1 = e0 + W_dev v_avg - (0.5 (p0 + p1) + q) dv, with p1 = a + b e1.
  const double rhs = in.energy_old + in.deviatoric_work * v_avg -
                     (0.5 * (in.pressure_old + in.pressure_offset_new) + step.bulk_viscosity) * dv;
  const double energy = rhs / (1.0 + 0.5 * in.pressure_slope_new * dv);
  return {energy, in.pressure_offset_new + in.pressure_slope_new * energy};
}

}  // namespace mpfd::mpm
