#pragma once
// A 1D radial solution handed to the Cartesian remap (S: the 1D spherical
// MPM, its particle state mapped to the radial grid, step (1)): N shells
// [r_k, r_{k+1}] with a uniform state in each.

#include <span>

namespace mpfd::coupler::remap {

struct RadialProfile {
  std::span<const double> edges;            ///< r_0 < r_1 < ... < r_N [m], r_0 >= 0
  std::span<const double> density;          ///< rho_k [kg/m^3], N values
  std::span<const double> velocity;         ///< radial velocity u_k [m/s]
  std::span<const double> internal_energy;  ///< specific internal energy e_k [J/kg]
  std::span<const int> material;            ///< material index >= 0 of each shell
  /// Optional (both empty or both N values): sigma_rr and the hoop stress
  /// sigma_tt = sigma_pp of each shell [Pa] (S: the spherically symmetric
  /// stress tensor is diag(sigma_rr, sigma_tt, sigma_pp)).
  std::span<const double> radial_stress;
  std::span<const double> hoop_stress;
};

/// Throws mpfd::Error naming the first inconsistent array or value.
void check_profile(const RadialProfile& profile);

/// Mass [kg], radial impulse sum m u [kg m/s] and total energy [J] of a
/// spherical profile: shell k holds rho_k 4 pi (r_{k+1}^3 - r_k^3) / 3.
struct SphericalTotals {
  double mass = 0.0;
  double radial_impulse = 0.0;
  double energy = 0.0;
  double radial_impulse_magnitude = 0.0;  ///< sum |m u|, the scale of its round-off
};

/// The whole profile's totals as a spherical one. Throws as check_profile.
[[nodiscard]] SphericalTotals profile_totals(const RadialProfile& profile);

}  // namespace mpfd::coupler::remap
