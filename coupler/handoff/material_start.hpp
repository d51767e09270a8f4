#pragma once
// Each material's own state in the cells at the AFDMP phase 1 -> 2 handoff
// (T §3.2.1 -> §3.2.2), the starting state of the FDM's mixed-cell closure
// (T (3-21)-(3-28)). T is silent on it: the FDM would start every material of
// a cell from the cell's own state (e_r = e_c, rho_r = rho_c), but the MPM
// particles know each material's mass, volume and energy exactly.
// Per cell c and material r, what the handoff knows of r in c: at mpm_to_fdm,
// over the particles whose position lies in c (a particle's whole mass, volume
// and energy to its cell: the cell_internal_energy and tracer binning of
// mpm_to_fdm.hpp),
//   m_r = sum m_p,  V_r = sum V_p,  E_r = sum e_p^int               (as T (3-5));
// at spherical_to_fdm, over the shells of material r overlapping c (S (17)-(19),
// coupler/remap/spherical_to_cartesian.hpp) and the ambient fill of what they
// leave uncovered.
// The cell's own totals stay those of T (3-3)-(3-8) (conservation is the
// cells' business, this changes none of them); the materials are made
// consistent with them by common factors:
//   theta_r = V_r / sum_s V_s                     T (3-23), the particles' volumes carried
//   rho_r   = (m_r / sum_s m_s) m_c / (theta_r V_c)   masses scaled to m_c: T (3-28) holds
//   e_r     = k E_r / m_r,  k with sum_r m_r' e_r = U_c,  m_r' = theta_r rho_r V_c
// where U_c = E_c V_c - |p_c|^2 / (2 m_c) is the cell's internal energy
// (T (3-5) plus the kinetic remainder mpm_to_fdm turns into heat, README
// reading 3). A common factor keeps the ratio e_1 : e_2 the particles have, as
// the closure's own rescaling does (fdm_solver/tracer/energy_split.hpp).
// A cell whose contributors hold one material gets theta = 1, rho_c, e_c for it
// (the FDM's export convention, proto/README.md §15 rule 6). A cell without a
// state -- no contributor, a material with m_r <= 0, V_r <= 0 or E_r <= 0, or
// m_c <= 0 or U_c <= 0 -- gets 0 for every material: the FDM then starts it
// from the cell's state, e_r = e_c, rho_r = rho_c (today's rule).

#include <cstddef>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"

namespace mpfd::coupler::handoff {

/// Per-material arrays laid out [c * material_count + r] (grid order of c),
/// shaped [n, materials] as the FDM's per-material quantities.
struct MaterialStart {
  int material_count = 0;
  std::vector<double> volume_fraction;  ///< theta_r [-]
  std::vector<double> density;          ///< rho_r [kg/m^3]
  std::vector<double> energy;           ///< e_r [J/kg]
  std::size_t mixed_cells = 0;          ///< cells whose contributors hold >= 2 materials
  std::size_t fallback_cells = 0;       ///< of those, left to the cell's state (see above)
  std::size_t empty_cells = 0;          ///< cells without a contributor (left to the cell's state)
};

/// Per cell and material, m_r [kg], V_r [m^3] and E_r [J] (internal), laid out
/// [c * material_count + r], and how many particles or shells gave them (a row
/// without contributors holds none of r).
struct MaterialSums {
  /// Zero sums for `cells` cells; throws mpfd::Error unless materials >= 1.
  MaterialSums(std::size_t cells, int materials);
  int material_count;
  std::vector<double> mass, volume, energy;
  std::vector<int> contributors;
};

/// The sums of `particles` (with their volumes `volume` [m^3]) per cell of
/// `grid`. Throws mpfd::Error naming a particle outside the grid, a material
/// outside [0, material_count), or an array of the wrong size.
[[nodiscard]] MaterialSums particle_material_sums(const grid::UniformGrid& grid,
                                                  const ParticleView& particles,
                                                  std::span<const double> volume,
                                                  int material_count);

/// The per-material start of every cell of `grid` from `sums` and the cells the
/// handoff made (whose totals the start is fitted to), fitted in place of the
/// sums' arrays (pass them moved at a large handoff). Throws mpfd::Error for an
/// array of the wrong size.
[[nodiscard]] MaterialStart material_start(const grid::UniformGrid& grid, MaterialSums sums,
                                           const ConservedView& cells);

/// material_start of particle_material_sums (mpm_to_fdm).
[[nodiscard]] MaterialStart material_start(const grid::UniformGrid& grid,
                                           const ParticleView& particles,
                                           std::span<const double> volume,
                                           const ConservedView& cells, int material_count);

}  // namespace mpfd::coupler::handoff
