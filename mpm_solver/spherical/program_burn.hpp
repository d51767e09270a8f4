#pragma once
// Program burn of T (3-1), (3-2) for a charge initiated at r = 0: a particle at
// initial radius r lights at t_L = r / D and its pressure is F p_JWL with
//   F = min(1, (t - t_L) D / (1.5 h)) for t >= t_L, 0 before,
// h the particle's characteristic length (T: 质点的特征长度); taken as the
// grid spacing, the h METHOD.md V10 states, so F ramps over about four steps
// at CFL 0.5 whatever the particle count.

#include <algorithm>

namespace mpfd::mpm::spherical {

[[nodiscard]] inline double burn_fraction(double time, double lighting_time,
                                          double detonation_velocity,
                                          double particle_length) noexcept {
  if (time < lighting_time) return 0.0;
  return std::min(1.0, (time - lighting_time) * detonation_velocity / (1.5 * particle_length));
}

}  // namespace mpfd::mpm::spherical
