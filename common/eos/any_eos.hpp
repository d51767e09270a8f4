#pragma once
// Every equation of state MPFD knows. Adding one = its own header/source plus
// one entry in this list (and its source in CMakeLists.txt).
//
// The free functions below visit the variant on every call: use them where it
// is not hot (setup, scene parsing, output, tests). A hot loop visits once and
// runs the whole loop inside, so the kernel is known at compile time, inlines
// and vectorises:
//   std::visit([&](const auto& eos) {
//     for (std::size_t i = 0; i < n; ++i) p[i] = eos.pressure(rho[i], e[i]);
//   }, material_eos);
// or, for code generic over the model: template <EquationOfState Eos> ...

#include <string_view>
#include <variant>

#include "common/eos/equation_of_state.hpp"
#include "common/eos/ideal_gas.hpp"
#include "common/eos/jwl.hpp"
#include "common/eos/mie_gruneisen.hpp"
#include "common/eos/polynomial.hpp"

namespace mpfd::eos {

using AnyEos = std::variant<IdealGas, Jwl, MieGruneisen, Polynomial>;

namespace detail {
template <class Variant>
inline constexpr bool all_equations_of_state = false;
template <class... Models>
inline constexpr bool all_equations_of_state<std::variant<Models...>> = (EquationOfState<Models> &&
                                                                         ...);
}  // namespace detail
static_assert(detail::all_equations_of_state<AnyEos>,
              "every AnyEos alternative must satisfy EquationOfState");

/// Pressure [Pa] at density rho [kg/m^3] and specific internal energy e [J/kg].
[[nodiscard]] double pressure(const AnyEos& eos, double rho, double e);
/// Sound speed [m/s] at (rho, e); floored as described in equation_of_state.hpp.
[[nodiscard]] double sound_speed(const AnyEos& eos, double rho, double e);
/// Specific internal energy [J/kg] that gives pressure p [Pa] at density rho.
[[nodiscard]] double internal_energy(const AnyEos& eos, double rho, double p);
/// The model's scene-file name: "ideal_gas", "jwl", "mie_gruneisen", "polynomial".
[[nodiscard]] std::string_view name(const AnyEos& eos);
/// Throws mpfd::Error "<model>: <parameter> must be <rule>, got <value>" for
/// the first bad parameter.
void validate(const AnyEos& eos);

}  // namespace mpfd::eos
