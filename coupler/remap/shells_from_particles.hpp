#pragma once
// The particles of the 1D spherical MPM (mpm_solver/spherical, seed S) as
// the radial shells the Cartesian remap takes (S step (1); design §3.5 H1s
// step 2). Particle k, ordered by radius, owns the shell between the
// mid-radii to its neighbours (0 below the first, `outer_radius` above the
// last) and keeps its mass, velocity and specific energy:
//   r_0 = 0,  r_k = (R_{k-1} + R_k) / 2,  r_N = outer_radius
//   rho_k = 3 m_k / (r_{k+1}^3 - r_k^3)    (m_k per steradian, S eq. (1))
//   u_k = v_k,  e_k = e_k,  sigma_k = sigma_k
// so the shells hold 4 pi m_k each, and the profile's mass, radial impulse
// and total energy equal the particles' (to round-off). The shell density is
// not the particle's own rho_p: the shells tile the ball, the particle
// volumes need not.

#include <span>
#include <vector>

#include "coupler/remap/radial_profile.hpp"

namespace mpfd::coupler::remap {

/// What the spherical MPM's export_profile gives, ordered by radius; the
/// caller maps each particle's layer to its scene material index.
struct SphericalParticleView {
  std::span<const double> radius;                    ///< R_k [m], strictly increasing, >= 0
  std::span<const double> mass_per_steradian;        ///< m_k [kg/sr]
  std::span<const double> velocity;                  ///< radial v_k [m/s]
  std::span<const double> specific_internal_energy;  ///< e_k [J/kg]
  std::span<const int> material;                     ///< material index >= 0
  /// Optional (both empty or both N values): sigma_rr, sigma_tt [Pa].
  std::span<const double> radial_stress;
  std::span<const double> hoop_stress;
};

/// Owning shells; view() is the RadialProfile the remap reads.
struct RadialShells {
  std::vector<double> edges;
  std::vector<double> density;
  std::vector<double> velocity;
  std::vector<double> internal_energy;
  std::vector<int> material;
  std::vector<double> radial_stress;
  std::vector<double> hoop_stress;

  [[nodiscard]] RadialProfile view() const;
};

/// Throws mpfd::Error for no particles, mismatched array sizes, radii not
/// strictly increasing or negative, a mass < 0, or outer_radius not above the
/// last particle.
[[nodiscard]] RadialShells shells_from_particles(const SphericalParticleView& particles,
                                                 double outer_radius);

/// Whole-sphere totals of the particles: 4 pi sum m_k, 4 pi sum m_k v_k,
/// 4 pi sum m_k (e_k + v_k^2 / 2).
[[nodiscard]] SphericalTotals particle_totals(const SphericalParticleView& particles);

}  // namespace mpfd::coupler::remap
