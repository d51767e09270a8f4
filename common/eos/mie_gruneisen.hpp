#pragma once
// Mie-Grueneisen with a linear Us-up Hugoniot reference, T (2-65), (2-66):
//   p = pH (1 - gamma mu / 2) + gamma rho e,  mu = rho/rho0 - 1,
//   pH = rho0 C0^2 [mu + (2S-1) mu^2 + (S-1)(3S-1) mu^3]   (mu > 0)
//   pH = rho0 C0^2 mu                                      (mu <= 0)
// with gamma = gamma0 constant. Writing pH' = dpH/dmu:
//   pH' = rho0 C0^2 [1 + 2(2S-1) mu + 3(S-1)(3S-1) mu^2]   (mu > 0)
//   pH' = rho0 C0^2                                        (mu <= 0)
//   (dp/drho)_e = [pH' (1 - gamma mu/2) - gamma pH / 2] / rho0 + gamma e
//   (dp/de)_rho = gamma rho,  c^2 = (dp/drho)_e + gamma p / rho
//   e(rho, p) = (p - pH (1 - gamma mu/2)) / (gamma rho)    (needs gamma0 > 0)
// Omitted: gamma rho = gamma0 rho0 (the other common variant), tension cut-off
// and spall (strength models own them).

#include <algorithm>
#include <string_view>

#include "common/eos/equation_of_state.hpp"

namespace mpfd::eos {

struct MieGruneisen {
  double rho0 = 0.0;    ///< reference density [kg/m^3]
  double c0 = 0.0;      ///< bulk sound speed, intercept of Us-up [m/s]
  double s = 0.0;       ///< slope of Us-up [-]
  double gamma0 = 0.0;  ///< Grueneisen coefficient [-]

  [[nodiscard]] static constexpr std::string_view name() noexcept { return "mie_gruneisen"; }

  /// Hugoniot pressure pH [Pa] and dpH/dmu [Pa] at compression mu = rho/rho0 - 1.
  [[nodiscard]] ValueAndSlope hugoniot_pressure(double mu) const noexcept {
    const double k = rho0 * c0 * c0;
    const double quadratic = 2.0 * s - 1.0;
    const double cubic = (s - 1.0) * (3.0 * s - 1.0);
    // m = max(mu, 0) selects the branch without a jump (see equation_of_state.hpp).
    const double m = std::max(mu, 0.0);
    return {k * (mu + m * m * (quadratic + m * cubic)),  // T (2-66)
            k * (1.0 + m * (2.0 * quadratic + 3.0 * cubic * m))};
  }

  /// Pressure [Pa] at density rho [kg/m^3] and specific internal energy e [J/kg].
  [[nodiscard]] double pressure(double rho, double e) const noexcept {
    const double mu = rho / rho0 - 1.0;
    return hugoniot_pressure(mu).value * (1.0 - 0.5 * gamma0 * mu) + gamma0 * rho * e;  // T (2-65)
  }

  /// Sound speed [m/s] from the analytic c^2 above.
  [[nodiscard]] double sound_speed(double rho, double e) const noexcept {
    const double mu = rho / rho0 - 1.0;
    const ValueAndSlope ph = hugoniot_pressure(mu);
    const double p = ph.value * (1.0 - 0.5 * gamma0 * mu) + gamma0 * rho * e;
    const double dp_drho =
        (ph.slope * (1.0 - 0.5 * gamma0 * mu) - 0.5 * gamma0 * ph.value) / rho0 + gamma0 * e;
    return sound_speed_from_squared(dp_drho + gamma0 * p / rho);
  }

  /// Specific internal energy [J/kg] giving pressure p [Pa] at density rho;
  /// +-inf or NaN if gamma0 == 0 (then p does not depend on e).
  [[nodiscard]] double internal_energy(double rho, double p) const noexcept {
    const double mu = rho / rho0 - 1.0;
    return (p - hugoniot_pressure(mu).value * (1.0 - 0.5 * gamma0 * mu)) /
           (gamma0 * rho);  // T (2-65) solved for e
  }
};

/// Throws mpfd::Error unless rho0 > 0, c0 > 0, s > 0 and gamma0 >= 0.
void validate(const MieGruneisen& eos);

}  // namespace mpfd::eos
