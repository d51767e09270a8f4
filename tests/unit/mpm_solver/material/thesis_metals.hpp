#pragma once
// The thesis's metals in SI. What the tables give, and the conversions:
//   T table 3.2 STEEL-1006, table 4.5 RHA, table 5.5 Al-2024 (Johnson-Cook):
//     E [MPa], A [MPa], B [MPa], n, C, rho [g/mm^3], nu.
//     MPa -> Pa: x 1e6.  g/mm^3 -> kg/m^3: x 1e6 (1e-3 kg per 1e-9 m^3),
//     so 0.00789 g/mm^3 = 7890 kg/m^3.  G = E / (2 (1 + nu)).
//   T table 3.3 (steels; RHA uses it too, T §4.4.5) and table 5.6 (Al-2024),
//   Mie-Grueneisen: C0 [m/s], S, gamma (= gamma0). rho0 is the strength
//   table's rho.
//   epsdot0 = 1/s is stated with (2-64) in T §2.3.4.
// Not in the thesis: m, T_melt, c_p (and T_room = 293 K). For STEEL-1006 and
// 2024-T351 the values below are those of Johnson & Cook 1983 (T ref. [130])
// as AUTODYN's library carries them: m = 1.0, T_melt = 1811 K / 775 K,
// c_p = 452 / 875 J/(kg K) -- quoted from memory, not from a seed. RHA's are
// not given anywhere in the seeds; a scene must supply them.
// Note: K = rho0 C0^2 from the EOS (steel: 164.7 GPa) is not E / (3 (1 - 2 nu))
// (177.2 GPa): the pressure, and so the bulk modulus, is the EOS's.

#include "common/config/scene.hpp"
#include "common/eos/mie_gruneisen.hpp"

namespace mpfd::mpm::test_support {

struct ThesisMetal {
  double youngs_modulus;  ///< E [Pa]
  double poisson_ratio;   ///< nu [-]
  config::JohnsonCook strength;
  eos::MieGruneisen eos;
};

inline constexpr double kMpa = 1e6;         // MPa -> Pa
inline constexpr double kGramPerMm3 = 1e6;  // g/mm^3 -> kg/m^3

[[nodiscard]] inline double shear_modulus(double e, double nu) {
  return e / (2.0 * (1.0 + nu));
}

/// Table 3.2 + table 3.3.
inline ThesisMetal steel_1006() {
  ThesisMetal m{212680 * kMpa, 0.3, {}, {0.00789 * kGramPerMm3, 4569, 1.49, 2.17}};
  m.strength.a = 350 * kMpa;
  m.strength.b = 275 * kMpa;
  m.strength.n = 0.36;
  m.strength.c = 0.022;
  m.strength.m = 1.0;
  m.strength.melt_temperature = 1811;
  m.strength.specific_heat = 452;
  m.strength.shear_modulus = shear_modulus(m.youngs_modulus, m.poisson_ratio);
  return m;
}

/// Table 4.5 + table 3.3; m, T_melt and c_p left at 0 (not given).
inline ThesisMetal rha() {
  ThesisMetal m{210000 * kMpa, 0.28, {}, {0.00785 * kGramPerMm3, 4569, 1.49, 2.17}};
  m.strength.a = 950 * kMpa;
  m.strength.b = 560 * kMpa;
  m.strength.n = 0.26;
  m.strength.c = 0.014;
  m.strength.shear_modulus = shear_modulus(m.youngs_modulus, m.poisson_ratio);
  return m;
}

/// Table 5.5 + table 5.6.
inline ThesisMetal al_2024() {
  ThesisMetal m{75000 * kMpa, 0.33, {}, {0.00277 * kGramPerMm3, 5350, 1.34, 2.0}};
  m.strength.a = 265 * kMpa;
  m.strength.b = 426 * kMpa;
  m.strength.n = 0.34;
  m.strength.c = 0.015;
  m.strength.m = 1.0;
  m.strength.melt_temperature = 775;
  m.strength.specific_heat = 875;
  m.strength.shear_modulus = shear_modulus(m.youngs_modulus, m.poisson_ratio);
  return m;
}

}  // namespace mpfd::mpm::test_support
