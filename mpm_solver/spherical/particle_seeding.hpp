#pragma once
// Places the particles of concentric layers on the radial grid. Each cell
// [a, a + h] gets n = particles_per_cell particles at its n Gauss-Legendre
// points r_j with volumes (per unit solid angle) V_j = (h/2) w_j r_j^2. For
// n >= 2 these volumes partition the cell's shell exactly,
//   sum_j V_j = ((a + h)^3 - a^3) / 3,
// so particle j owns a sub-shell (r1, r2) with (r2^3 - r1^3)/3 = V_j and its
// mass is S eq. (1), m = rho (r2^3 - r1^3) / 3. Placing them at Gauss points
// makes the particle quadrature of the weak form exact at t = 0 for linear
// shape functions (the integrands times r^2 are cubic at most), so a uniform
// stress produces no nodal force, at r = 0 or elsewhere. With GIMP shapes the
// particles sit at the middle of n equal sub-shells instead, which their GIMP
// domains tile (radial_shape.hpp); the mass is again S eq. (1).

#include <vector>

#include "mpm_solver/spherical/spherical_particles.hpp"
#include "mpm_solver/spherical/spherical_setup.hpp"

namespace mpfd::mpm::spherical {

/// Throws mpfd::Error for an empty layer list, radii not increasing or not on a
/// grid line, a non-positive density, fewer than 2 particles per cell, or an
/// explosive layer whose material has no explosive section.
void validate(const std::vector<RadialLayer>& layers, const SphericalOptions& options);

/// Fills radius, mass, density, energy, material, lighting time and burn fraction
/// (F = 0 for explosive particles, 1 otherwise); other fields are zero.
void seed_particles(const std::vector<RadialLayer>& layers, const SphericalOptions& options,
                    std::size_t history_stride, SphericalParticles& particles);

}  // namespace mpfd::mpm::spherical
