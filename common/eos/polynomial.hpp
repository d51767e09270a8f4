#pragma once
// Polynomial EOS (AUTODYN form; seed S uses it for water but its equation was
// lost in extraction), mu = rho/rho0 - 1:
//   mu > 0:  p = A1 mu + A2 mu^2 + A3 mu^3 + (B0 + B1 mu) rho0 e
//   mu <= 0: p = T1 mu + T2 mu^2 + B0 rho0 e
// Water (AUTODYN library): rho0 = 1000, A1 = 2.2e9, A2 = 9.54e9, A3 = 1.457e10,
// B0 = B1 = 0.28, T1 = 2.2e9, T2 = 0.
// Writing p = p_ref(mu) + b(mu) rho0 e with b = B0 + B1 mu (mu > 0), B0 (mu <= 0):
//   (dp/drho)_e = dp_ref/dmu / rho0 + B1 e (mu > 0; no B1 term for mu <= 0)
//   (dp/de)_rho = b rho0,  c^2 = (dp/drho)_e + p/rho^2 b rho0
//   e(rho, p) = (p - p_ref) / (b rho0)                    (needs b != 0)
// p is continuous at mu = 0 (both branches give B0 rho0 e); its slope is not
// unless A1 = T1. Omitted: AUTODYN's tension cut-off (the caller clamps p).

#include <algorithm>
#include <string_view>

#include "common/eos/equation_of_state.hpp"

namespace mpfd::eos {

struct Polynomial {
  double rho0 = 0.0;  ///< reference density [kg/m^3]
  double a1 = 0.0;    ///< [Pa]
  double a2 = 0.0;    ///< [Pa]
  double a3 = 0.0;    ///< [Pa]
  double b0 = 0.0;    ///< [-]
  double b1 = 0.0;    ///< [-]
  double t1 = 0.0;    ///< [Pa]
  double t2 = 0.0;    ///< [Pa]

  [[nodiscard]] static constexpr std::string_view name() noexcept { return "polynomial"; }

  /// The e = 0 part p_ref [Pa] and dp_ref/dmu [Pa] at compression mu = rho/rho0 - 1.
  [[nodiscard]] ValueAndSlope reference_pressure(double mu) const noexcept {
    // Branch-free select (see equation_of_state.hpp): one of mc (compression)
    // and mt (tension) is always 0, and `compressed` is a 0/1 weight.
    const double mc = std::max(mu, 0.0);
    const double mt = std::min(mu, 0.0);
    const double compressed = mu > 0.0 ? 1.0 : 0.0;
    return {mc * (a1 + mc * (a2 + mc * a3)) + mt * (t1 + mt * t2),
            compressed * (a1 + mc * (2.0 * a2 + 3.0 * mc * a3)) +
                (1.0 - compressed) * (t1 + 2.0 * mt * t2)};
  }

  /// b(mu) = (dp/de)_rho / rho0 [-]: B0 + B1 mu in compression, B0 in tension.
  [[nodiscard]] double energy_coefficient(double mu) const noexcept {
    return b0 + b1 * std::max(mu, 0.0);
  }

  /// Pressure [Pa] at density rho [kg/m^3] and specific internal energy e [J/kg].
  [[nodiscard]] double pressure(double rho, double e) const noexcept {
    const double mu = rho / rho0 - 1.0;
    return reference_pressure(mu).value + energy_coefficient(mu) * rho0 * e;
  }

  /// Sound speed [m/s] from the analytic c^2 above.
  [[nodiscard]] double sound_speed(double rho, double e) const noexcept {
    const double mu = rho / rho0 - 1.0;
    const ValueAndSlope ref = reference_pressure(mu);
    const double dp_de = energy_coefficient(mu) * rho0;
    const double p = ref.value + dp_de * e;
    const double dp_drho = ref.slope / rho0 + (mu > 0.0 ? b1 * e : 0.0);
    return sound_speed_from_squared(dp_drho + p / (rho * rho) * dp_de);
  }

  /// Specific internal energy [J/kg] giving pressure p [Pa] at density rho;
  /// +-inf or NaN where b(mu) == 0 (then p does not depend on e).
  [[nodiscard]] double internal_energy(double rho, double p) const noexcept {
    const double mu = rho / rho0 - 1.0;
    return (p - reference_pressure(mu).value) / (energy_coefficient(mu) * rho0);
  }
};

/// Throws mpfd::Error unless rho0 > 0, a1 > 0 and t1 > 0.
void validate(const Polynomial& eos);

}  // namespace mpfd::eos
