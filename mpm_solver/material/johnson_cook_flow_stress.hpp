#pragma once
// Johnson-Cook flow stress, T (2-64):
//   sigma_y = (A + B eps_p^n) (1 + C ln epsdot*) (1 - T*^m),
//   epsdot* = max(epsdot_p / epsdot0, 1),  T* = clamp((T - T_room) / (T_melt - T_room), 0, 1).
// The rate is the equivalent plastic strain rate Delta eps_p / dt of the
// step, so the return map is implicit in it; it is floored at the reference
// rate so the log never weakens the metal. T* is clamped: below room
// temperature the metal does not harden, at and above T_melt it has no strength.
// For the return map the flow stress is a function of the step's plastic
// strain increment x = Delta eps_p at a temperature fixed over the step.

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/config/scene.hpp"

namespace mpfd::mpm {

struct FlowStressAndSlope {
  double value = 0.0;  ///< sigma_y [Pa]
  double slope = 0.0;  ///< d sigma_y / d(Delta eps_p) [Pa], >= 0 (may be +inf)
};

class JohnsonCookFlowStress {
 public:
  explicit JohnsonCookFlowStress(const config::JohnsonCook& p) : p_(p) {}

  /// 1 - T*^m [-] at temperature T [K].
  [[nodiscard]] double thermal_factor(double temperature) const noexcept {
    const double homologous = std::clamp(
        (temperature - p_.room_temperature) / (p_.melt_temperature - p_.room_temperature), 0.0,
        1.0);
    return 1.0 - std::pow(homologous, p_.m);
  }

  /// sigma_y and its slope after a plastic increment x >= 0 over a step dt
  /// from plastic strain eps_p, with the step's thermal factor. A step with
  /// dt <= 0 has no rate to speak of and takes the reference rate.
  [[nodiscard]] FlowStressAndSlope after_increment(double eps_p, double x, double dt,
                                                   double thermal) const noexcept {
    const double strain = eps_p + x;
    const double hardening = p_.a + p_.b * std::pow(strain, p_.n);
    // d/dx of B strain^n; n = 0 or B = 0 has none, n < 1 is infinite at strain 0.
    const double hardening_slope = p_.b * p_.n == 0.0 ? 0.0
                                   : strain > 0.0     ? p_.b * p_.n * std::pow(strain, p_.n - 1.0)
                                                      : std::numeric_limits<double>::infinity();
    const double rate = dt > 0.0 ? x / (dt * p_.reference_strain_rate) : 0.0;
    const double rate_term = 1.0 + p_.c * std::log(std::max(rate, 1.0));
    const double rate_slope = rate > 1.0 ? p_.c / x : 0.0;
    return {hardening * rate_term * thermal,
            (hardening_slope * rate_term + hardening * rate_slope) * thermal};
  }

 private:
  config::JohnsonCook p_;
};

}  // namespace mpfd::mpm
