#pragma once
// Conservative remap of a 1D radial profile onto a uniform Cartesian grid
// (S, "重映射" steps (1)-(4); AUTODYN's 1D -> 3D remap, S ref. [14]).
//   3D grid: spherical profile, shells are balls' differences.
//   2D grid (x, y active, z inactive): cylindrical profile about the z axis
//   through `centre`, per the grid's thickness along z.
// Each cell-shell overlap V_ck is the exact intersection measure
// (ball_box_overlap), not a subcell sample, so a cell gets exactly the mass
// of what it covers and mass is conserved to round-off with no tuning.
// Then with n = (x_c - centre)/|x_c - centre| (S (17), the first row of R):
//   m_c = sum_k rho_k V_ck
//   P_c = sum_k rho_k u_k V_ck,   p_c = P_c n           S (18): v = R^T (u, 0, 0)
//   E_c = sum_k rho_k (e_k + u_k^2/2) V_ck
//   sigma_c = sum_k V_ck [sigma_tt,k I + (sigma_rr,k - sigma_tt,k) n n^T] / sum_k V_ck   S (19)
// Mass, total energy and the radial impulse sum_c P_c = sum_k m_k u_k are
// conserved to round-off over the part of the profile inside the grid (the
// rest is reported). A cell's kinetic energy |p_c|^2/(2 m_c) is at most its
// share of sum_k m_k u_k^2/2 (Jensen); the difference stays in E_c, i.e.
// becomes internal energy, as in any conservative remap. A cell whose centre
// is the symmetry centre has no direction n: its momentum is set to zero
// and its radial impulse becomes internal energy (it is zero for a profile
// that is at rest at r = 0).

#include <array>
#include <cstddef>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "coupler/remap/radial_profile.hpp"

namespace mpfd::coupler::remap {

struct CartesianFields {
  std::vector<double> density;                  ///< m_c / V_c [kg/m^3]
  std::array<std::vector<double>, 3> momentum;  ///< p_c / V_c [kg/(m^2 s)]
  std::vector<double> total_energy;             ///< E_c / V_c [J/m^3]
  std::vector<double> covered_fraction;         ///< sum_k V_ck / V_c; < 1 where the profile ends
  int material_count = 0;
  // Per-material arrays: [c * material_count + r], shape [n, materials] as in proto §7.
  std::vector<double> volume_fraction;  ///< sum_{k of r} V_ck / V_c
  std::vector<double> material_mass;    ///< [kg]
  /// sum_{k of r} rho_k e_k V_ck [J], so that rho_r = m_r / (theta_r V_c)
  /// and e_r = this / m_r feed handoff::fdm_to_mpm (S step (4)).
  std::vector<double> material_internal_energy;
  /// Voigt xx, yy, zz, yz, xz, xy per cell [Pa] (as proto particles.proto);
  /// empty unless the profile has stresses.
  std::array<std::vector<double>, 6> stress;
};

/// What the grid holds of the profile: mass [kg], total energy [J] and
/// radial impulse sum m u [kg m/s], from the shells' exact overlap with the
/// whole grid box; a spherical profile's own totals are profile_totals()
/// (radial_profile.hpp).
struct RemapTotals {
  double mass = 0.0;
  double energy = 0.0;
  double radial_impulse = 0.0;
};

/// Throws mpfd::Error for a 1D grid, a 2D grid whose inactive axis is not z,
/// or an inconsistent profile.
[[nodiscard]] CartesianFields remap_radial_profile(const grid::UniformGrid& grid,
                                                   const grid::Vec3& centre,
                                                   const RadialProfile& profile);

/// The totals of the profile inside the grid box.
[[nodiscard]] RemapTotals totals_inside_grid(const grid::UniformGrid& grid,
                                             const grid::Vec3& centre,
                                             const RadialProfile& profile);

}  // namespace mpfd::coupler::remap
