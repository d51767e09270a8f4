#pragma once
// Materials of the seeds in SI units, shared by the EOS tests.

#include "common/eos/ideal_gas.hpp"
#include "common/eos/jwl.hpp"
#include "common/eos/mie_gruneisen.hpp"
#include "common/eos/polynomial.hpp"

namespace mpfd::eos::test_materials {

/// Air, T (2-59) and METHOD §3: gamma = 1.4 (rho = 1.225 kg/m^3, e = 2.0685e5 J/kg).
inline constexpr IdealGas kAir{.gamma = 1.4};
inline constexpr double kAirDensity = 1.225;
inline constexpr double kAirEnergy = 2.0685e5;

/// TNT, T Table 3.1 converted from mm-g-ms-MPa-mJ to SI.
inline constexpr Jwl kTnt{.rho0 = 1630.0,
                          .a = 371.2e9,
                          .b = 3.21e9,
                          .r1 = 4.15,
                          .r2 = 0.95,
                          .omega = 0.3,
                          .detonation_energy = 6.993e9};

/// STEEL-1006, T Tables 3.2 (rho = 0.00789 g/mm^3) and 3.3.
inline constexpr MieGruneisen kSteel{.rho0 = 7890.0, .c0 = 4569.0, .s = 1.49, .gamma0 = 2.17};

/// Water, AUTODYN library values quoted in polynomial.hpp.
inline constexpr Polynomial kWater{.rho0 = 1000.0,
                                   .a1 = 2.2e9,
                                   .a2 = 9.54e9,
                                   .a3 = 1.457e10,
                                   .b0 = 0.28,
                                   .b1 = 0.28,
                                   .t1 = 2.2e9,
                                   .t2 = 0.0};

}  // namespace mpfd::eos::test_materials
