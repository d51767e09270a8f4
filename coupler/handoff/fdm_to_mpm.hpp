#pragma once
// AFDMP handoff from phase 2 (FDM) to phase 3 (MPM with FSI), T §3.2.3.
// Single-material cell (tracers discarded), 2^d regular particles
// (8 in 3D, 4 in 2D, 2 in 1D) at x_ic +- h_i / 4:               T (3-18)
//   m_p = rho_c V_c / 2^d,  v_p = (rho v)_c / rho_c,              T (3-14), (3-15)
//   e_p^int = e_c^int / 2^d,  sigma_p = -p_c I                    T (3-16), (3-17)
// with e_c^int = E_c V_c - m_c |v_c|^2 / 2 the cell's internal energy [J].
// Mixed cell: each tracer of material r becomes a particle at its position:
//   m_rp = rho_rc theta_r V_c / n_br,  e_rp^int = e_rc^int / n_br  T (3-19), (3-20)
// where e_rc^int is material r's internal energy in the cell [J] (T writes
// e^int for both the specific e_r of §3.3 and the extensive energy; only the
// extensive reading makes (3-20) conserve). Velocity and pressure as in a
// single-material cell (T: "other variables as for single-material cells").
// Conservation to round-off whatever the closure's tolerance:
//   masses m_r = rho_r theta_r V_c are scaled by m_c / sum_r m_r (T (3-28)
//   says the factor is 1);
//   e_rc^int = m_r e_r + theta_r (e_c^int - sum_s m_s e_s), the defect split
//   by volume fraction like the energy increment of T §3.3 (2).
// A material with theta_r > 0 but no tracer in the cell gets 2^d regular
// particles (T does not say; dropping it would lose its mass). Cells with
// rho_c = 0 produce no particles.
// Volumes (T gives none; the MPM needs V_p): V_c / 2^d per regular particle;
// in a mixed cell theta_r V_c / n_br, with the theta_r normalised by
// sum_s theta_s like the masses, so that the volumes of every cell's
// particles sum to V_c whatever the closure's tolerance.

#include <cstddef>
#include <span>

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"

namespace mpfd::coupler::handoff {

/// Marks a mixed cell in FdmEnd::cell_material (as fdm::kMixedCell).
inline constexpr int kMixedCell = -1;

/// The FDM state at the end of phase 2; per-material arrays are laid out
/// [c * material_count + r] (shape [n, materials] as in proto/README.md §7)
/// and read only where theta_r > 0 in a mixed cell.
struct FdmEnd {
  ConservedView cells;
  std::span<const double> pressure;    ///< p_c [Pa]
  std::span<const int> cell_material;  ///< material of the cell, or kMixedCell
  int material_count = 0;
  std::span<const double> volume_fraction;   ///< theta_r [-]
  std::span<const double> material_density;  ///< rho_r [kg/m^3]
  std::span<const double> material_energy;   ///< e_r [J/kg]
  TracerView tracers;
};

/// T (3-14)-(3-20). Throws mpfd::Error on a size mismatch, a material index
/// out of range, a tracer outside the grid, or a mixed cell with mass but
/// sum_r rho_r theta_r = 0.
[[nodiscard]] ParticleSet fdm_to_mpm(const grid::UniformGrid& grid, const FdmEnd& state);

}  // namespace mpfd::coupler::handoff
