#pragma once
// Artificial bulk viscosity, S eq. (16) (lost in extraction; rebuilt in the
// standard linear + quadratic form of S's reference [16], Zhang & Wang 2007):
//   q = rho l_e (c0 l_e epsdot_kk^2 - c1 c epsdot_kk)   for epsdot_kk < 0
//   q = 0                                              otherwise
// rho current density, l_e the background grid spacing (S), epsdot_kk the
// volumetric strain rate, c the sound speed. q adds to the pressure in the
// stress of the momentum equation and in the energy equation (2-4).

#include "mpm_solver/spherical/spherical_setup.hpp"

namespace mpfd::mpm::spherical {

[[nodiscard]] inline double bulk_viscosity(const BulkViscosity& coefficients, double rho,
                                           double length, double volumetric_rate,
                                           double sound_speed) noexcept {
  if (volumetric_rate >= 0.0) return 0.0;
  return rho * length *
         (coefficients.quadratic * length * volumetric_rate * volumetric_rate -
          coefficients.linear * sound_speed * volumetric_rate);  // S eq. (16)
}

/// The viscous part of the effective wave speed for the stable step:
/// Q = c1 c + c0 l_e |epsdot_kk| when compressing (q = rho Q l_e |epsdot_kk|).
[[nodiscard]] inline double viscous_speed(const BulkViscosity& coefficients, double length,
                                          double volumetric_rate, double sound_speed) noexcept {
  if (volumetric_rate >= 0.0) return 0.0;
  return coefficients.linear * sound_speed - coefficients.quadratic * length * volumetric_rate;
}

}  // namespace mpfd::mpm::spherical
