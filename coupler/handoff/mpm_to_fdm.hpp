#pragma once
// AFDMP handoff from phase 1 (MPM detonation) to phase 2 (FDM blast), T §3.2.1.
// The MPM background grid nodes are the FDM cell corners. Steps:
//   m_I = sum_p N_Ip m_p,  p_iI = sum_p N_Ip m_p v_ip          T (2-12), (2-9)
//   K_I = sum_p N_Ip m_p |v_p|^2 / 2       (nodal kinetic energy, see below)
//   m_c = sum_I m_I N_Ic,  p_ic = sum_I p_iI N_Ic              T (3-3), (3-4)
//   e_c^int = sum_{p in c} e_p^int                             T (3-5)
//   rho_c = m_c / V_c,  (rho v)_c = rho_c p_c / m_c = p_c / V_c T (3-6), (3-7)
//   E_c = (e_c^int + K_c) / V_c,  K_c = sum_I K_I N_Ic          T (3-8), read conservatively
// T (3-8) writes K_c = m_c |p_c / m_c|^2 / 2. That drops the kinetic energy
// the two averagings remove (>= 0 by Jensen, 0 for a uniform velocity), so
// total energy would not be conserved as T §3.2.1 says it is; K_c keeps it,
// and K_c - |p_c|^2 / (2 m_c) >= 0 becomes internal energy of the cell.
// Without K_I (an MPM that exports only node_mass, node_momentum and
// cell_internal_energy, proto/README.md §7) T (3-8) is applied as printed.
// N_Ic is renormalised on boundary nodes (grid_stencil.hpp). Particles become
// massless tracers keeping position and material (T §3.2.1, last paragraph).

#include <array>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"

namespace mpfd::coupler::handoff {

/// Nodal fields in grid::UniformGrid::node_index order.
struct NodalFields {
  std::vector<double> mass;                     ///< m_I [kg]
  std::array<std::vector<double>, 3> momentum;  ///< p_iI [kg m/s]
  std::vector<double> kinetic_energy;           ///< K_I [J]; empty: T (3-8) as printed
};

struct FdmCells {
  ConservedCells cells;
  /// sum_c (K_c - |p_c|^2 / (2 m_c)) [J]: kinetic energy the projection made
  /// internal (0 when T (3-8) is applied as printed, which loses it instead).
  double kinetic_to_internal = 0.0;
};

struct FdmStart {
  ConservedCells cells;
  TracerPoints tracers;
  double kinetic_to_internal = 0.0;  ///< as FdmCells
};

/// T (2-12), (2-9) and K_I. Throws mpfd::Error naming a particle outside
/// the grid or an array of the wrong size.
[[nodiscard]] NodalFields scatter_to_nodes(const grid::UniformGrid& grid,
                                           const ParticleView& particles);

/// T (3-5): e_c^int [J] of every cell, the sum over the particles in it.
[[nodiscard]] std::vector<double> cell_internal_energy(const grid::UniformGrid& grid,
                                                       const ParticleView& particles);

/// The particles as massless tracers: position and material.
[[nodiscard]] TracerPoints tracers_from_particles(const ParticleView& particles);

/// T (3-3), (3-4), (3-6)-(3-8) from nodal fields and e_c^int per cell.
/// Throws mpfd::Error if an array does not match the grid's node or cell count.
[[nodiscard]] FdmCells cells_from_nodes(const grid::UniformGrid& grid, const NodalFields& nodes,
                                        std::span<const double> cell_internal_energy);

/// The whole handoff from the particles alone (conservative: K_I included).
[[nodiscard]] FdmStart mpm_to_fdm(const grid::UniformGrid& grid, const ParticleView& particles);

}  // namespace mpfd::coupler::handoff
