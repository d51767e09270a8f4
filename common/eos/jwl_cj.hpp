#pragma once
// Chapman-Jouguet (CJ) state of a JWL explosive, for the program burn and the
// detonation tests. With the relative volume V = rho0/rho, E the internal
// energy per unit initial volume (as in jwl.hpp) and the unreacted explosive
// at (V = 1, p = 0, E = E0):
//   products' Hugoniot  E = E0 + p (1 - V)/2, with p = p_ref(V) + w E / V (T (2-60)):
//     pH(V) = (p_ref(V) + w E0 / V) / (1 - w (1 - V) / (2V)),  V > w / (2 + w)
//   Rayleigh line       p = rho0 D^2 (1 - V)
// The CJ point is where the Rayleigh line touches the Hugoniot, i.e. where the
// Rayleigh slope pH/(1 - V) is least: d/dV [pH/(1 - V)] = 0, or
//   pH'(V) (1 - V) + pH(V) = 0.
// Then D = sqrt(p / (rho0 (1 - V))) (= v0 sqrt(p / (v0 - v)) in specific
// volumes), u = D (1 - V), rho = rho0 / V.

#include "common/eos/jwl.hpp"

namespace mpfd::eos {

struct ChapmanJouguetState {
  double pressure;             ///< p_CJ [Pa]
  double detonation_velocity;  ///< D_CJ [m/s]
  double density;              ///< rho_CJ [kg/m^3]
  double particle_velocity;    ///< u_CJ [m/s], lab frame, explosive ahead at rest
};

/// The products' Hugoniot pressure pH [Pa] and dpH/dV [Pa] at relative volume
/// v = rho0/rho; defined for v > omega / (2 + omega) (the pole of pH).
[[nodiscard]] ValueAndSlope products_hugoniot(const Jwl& eos, double v) noexcept;

/// The CJ state. Validates eos first (mpfd::Error on bad parameters) and throws
/// mpfd::Error if the Hugoniot has no tangent point in (omega/(2+omega), 1).
[[nodiscard]] ChapmanJouguetState chapman_jouguet_state(const Jwl& eos);

}  // namespace mpfd::eos
