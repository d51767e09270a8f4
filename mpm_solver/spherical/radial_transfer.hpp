#pragma once
// The particle-grid transfers of one explicit MUSL step, T (2-9)-(2-17), in
// the spherically symmetric form of seed S. Equations marked "rebuilt" were
// lost from S's extraction and are derived in README.md.
//
// With w(r) a radial test function, the weak form per unit solid angle is
//   int rho a w r^2 dr + int (sigma_rr w' + 2 sigma_tt w / r) r^2 dr = [t w r^2]_boundary
// and with rho = sum_p m_p delta(r - r_p) / r^2 (S eq. (3)), V_p = m_p / rho_p:
//   f_I^int = - sum_p V_p (sigma_rr,p N_I'(r_p) + 2 sigma_tt,p N_I(r_p) / r_p)   S eq. (7), rebuilt
// (with GIMP, N_I' -> B_I and N_I / r_p -> C_I of radial_shape.hpp).

#include <cstddef>
#include <vector>

#include "mpm_solver/spherical/radial_grid.hpp"
#include "mpm_solver/spherical/radial_shape.hpp"
#include "mpm_solver/spherical/spherical_particles.hpp"
#include "mpm_solver/spherical/spherical_setup.hpp"

namespace mpfd::mpm::spherical {

/// Each particle's weights at the start of the step, N_Ip^n.
using ParticleWeights = std::vector<RadialWeights>;

/// Node mass (2-12), momentum (2-9) and internal force (S eq. (7)); weights^n.
/// half_width_cells: the GIMP shell half-width l / h (unused for linear).
void scatter_to_grid(const SphericalParticles& particles, RadialShape shape,
                     double half_width_cells, RadialGrid& grid, ParticleWeights& weights);

/// Adds the traction -(p_ambient + rho c v) at the outer surface r_s (the
/// outer edge of the outermost particle's shell, the particle at its middle), rho c of the
/// outermost particle: a plane-wave non-reflecting boundary (exact for r >> wavelength) that holds
/// the medium's initial pressure. The rho c v part is a dashpot integrate_grid() takes implicitly.
void add_transmitting_traction(const SphericalParticles& particles, double ambient_pressure,
                               RadialGrid& grid);

/// p_I^{n+1} = p_I^n + f_I dt (2-13), with p = f = 0 at the centre node and the
/// boundary dashpot at v^{n+1}; leaves f_I = (p_I^{n+1} - p_I^n) / dt for (2-15).
void integrate_grid(RadialGrid& grid, double dt);

/// v_p += sum_I N_Ip f_I / m_I dt (2-15), r_p += sum_I N_Ip p_I^{n+1} / m_I dt (2-16).
/// Throws mpfd::Error if a particle leaves the grid.
void update_particle_motion(SphericalParticles& particles, const RadialGrid& grid,
                            const ParticleWeights& weights, double dt);

/// v_I^{n+1} = sum_p m_p N_Ip^n v_p^{n+1} / m_I (2-17), zero at the centre node.
void remap_grid_velocity(const SphericalParticles& particles, const ParticleWeights& weights,
                         RadialGrid& grid);

}  // namespace mpfd::mpm::spherical
