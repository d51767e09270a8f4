#pragma once
// The contract every equation of state (EOS) in MPFD satisfies, and what the
// models share. An EOS closes the Euler / MPM energy equation: pressure p [Pa]
// from density rho [kg/m^3] and specific internal energy e [J/kg].
//
// Every model here is affine in e at fixed rho, p = p_ref(rho) + k(rho) e, so
//   c^2 = (dp/drho)_e + p/rho^2 (dp/de)_rho   (isentropic, de = p/rho^2 drho)
// and the inverse e(rho, p) = (p - p_ref) / k are closed form.
//
// Kernels select branches with max/min/?: on values, never with jumps. GCC 12
// vectorises loops over them only with -fno-math-errno (sqrt) and
// -fno-trapping-math (the selects); JWL's exp also needs a vector libm.

#include <algorithm>
#include <cmath>
#include <concepts>
#include <string_view>
#include <type_traits>

namespace mpfd::eos {

/// Floor on c^2 [m^2/s^2] (c = 1e-6 m/s). Outside a model's range (strong
/// tension, e < 0 after a numerical undershoot) the analytic c^2 can be <= 0:
/// the state is thermodynamically unstable and sqrt would give NaN, which
/// poisons the CFL minimum and the acoustic impedances rho c. The floor keeps c
/// real and positive and is ~17 orders below any physical c^2 (air: 1.2e5), so
/// it never changes a physical answer. NaN inputs stay NaN so bad states show.
inline constexpr double kMinSoundSpeedSquared = 1e-12;

/// sqrt(max(c2, kMinSoundSpeedSquared)) [m/s]; a NaN c2 stays NaN.
[[nodiscard]] inline double sound_speed_from_squared(double c2) noexcept {
  return std::sqrt(std::max(c2, kMinSoundSpeedSquared));
}

/// A curve and its derivative at one point, e.g. a reference pressure p_ref
/// and dp_ref/dV.
struct ValueAndSlope {
  double value;
  double slope;
};

/// A point-kernel EOS: plain trivially copyable parameters, pure noexcept
/// kernels (no allocation, no I/O) and a validate() found by ADL that throws
/// mpfd::Error naming the bad parameter.
template <class T>
concept EquationOfState = std::is_trivially_copyable_v<T> &&
    requires(const T& eos, double rho, double e, double p) {
  { T::name() } -> std::same_as<std::string_view>;
  { eos.pressure(rho, e) } -> std::same_as<double>;
  { eos.sound_speed(rho, e) } -> std::same_as<double>;
  { eos.internal_energy(rho, p) } -> std::same_as<double>;
  requires noexcept(eos.pressure(rho, e));
  requires noexcept(eos.sound_speed(rho, e));
  requires noexcept(eos.internal_energy(rho, p));
  validate(eos);
};

}  // namespace mpfd::eos
