#pragma once
// The particle half of the MUSL step after the remap (2-17): strain increments
// in spherical symmetry (S eq. (11), rebuilt)
//   Delta eps_rr = sum_I N_I,r(r_p^n) v_I^{n+1} dt
//   Delta eps_tt = Delta eps_pp = sum_I N_I(r_p^n) v_I^{n+1} / r_p^n dt
// (the spin is zero), the density (2-20) rho^{n+1} = rho^n / (1 + tr Delta eps),
// the bulk viscosity q (S eq. (16)), the burn fraction (T (3-2)), and the
// material's update through ConstitutiveModel with
// StrainStep::strain_increment = diag(Delta eps_rr, Delta eps_tt, Delta eps_tt).

#include <vector>

#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/spherical/radial_grid.hpp"
#include "mpm_solver/spherical/radial_transfer.hpp"
#include "mpm_solver/spherical/spherical_particles.hpp"
#include "mpm_solver/spherical/spherical_setup.hpp"

namespace mpfd::mpm::spherical {

/// Per-material data the stress update needs, indexed like SphericalParticles::material.
struct MaterialTable {
  std::vector<const ConstitutiveModel*> models;
  std::vector<double> detonation_velocity;  ///< D [m/s] of explosive layers, 0 otherwise
};

struct StressUpdateSettings {
  BulkViscosity viscosity;
  double viscous_length = 0.0;   ///< l_e = grid spacing [m], S eq. (16)
  double particle_length = 0.0;  ///< h of T (3-2) [m], the grid spacing (program_burn.hpp)
};

/// Advances density, q, F and the constitutive state of every particle to time_new.
void update_particle_stress(SphericalParticles& particles, const RadialGrid& grid,
                            const ParticleWeights& weights, const MaterialTable& materials,
                            const StressUpdateSettings& settings, double time_new, double dt);

}  // namespace mpfd::mpm::spherical
