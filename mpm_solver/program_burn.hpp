#pragma once
// The program burn ("真实起爆模型", T §3.2.1): a particle of explosive lights
// at t_L = distance from the detonation point / D, and its pressure is the
// JWL pressure times the burn fraction, p = F p_E (3-1), with
//   F = (t - t_L) D / (1.5 h) for t >= t_L, 0 before, capped at 1 (3-2),
// h the particle's characteristic length. Inert particles and an
// instantaneous burn have t_L = -inf: F = 1 from the start.

#include <algorithm>
#include <cmath>

namespace mpfd::mpm {

/// F of T (3-2) at time t for lighting time t_L and rate = D / (1.5 h).
[[nodiscard]] inline double burn_fraction(double t, double lighting_time, double rate) noexcept {
  if (std::isinf(lighting_time)) return 1.0;
  return std::clamp((t - lighting_time) * rate, 0.0, 1.0);
}

}  // namespace mpfd::mpm
