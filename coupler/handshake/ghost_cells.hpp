#pragma once
// FDM ghost cells from the MPM background grid, T §4.2.2, (4-1) ... (4-6).
// A ghost cell c (cells k+1... of T Fig. 4.3, region `ghost_cells`) is an MPM
// background cell; its centre sees its 2^Dim corner nodes I with the
// (tri)linear weight N_Ic = 2^-Dim:
//   m_c = Σ_I N_Ic m_I,   p_c = Σ_I N_Ic p_I                   T (4-1), (4-2)
//   e_c^int = Σ_{p in c} e_p^int                               T (4-3)
//   ρ_c = m_c / V_c,  (ρv)_c = ρ_c p_c / m_c,
//   E_c = (e_c^int + ½ m_c |p_c / m_c|²) / V_c                 T (4-4) ... (4-6)
// (4-6) prints (p_ic / m_c)²: read as the sum over i, |v_c|². A nodal mass m_I
// is the mass of the node's volume V_c, so a uniform MPM state gives the
// ghost cells that state. The corner nodes need full support inside the MPM
// zone (w >= 1 for linear shape functions). A node on a domain face (wall,
// symmetry, outflow) has only the part of V_c inside the domain, half per
// face: m_c, p_c, e_c are divided by the volume their corner nodes hold,
// V_c Σ_I N_Ic s_I (s_I = 1/2 per face the node lies on), not by V_c — else a
// ghost cell along a wall got 3/4 of the density (2D) at the right pressure.
// e_c^int comes from the MPM with the support of (4-1) (mpm_solver serve).

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "coupler/handshake/fields.hpp"
#include "coupler/handshake/index_box.hpp"

namespace mpfd::coupler::handshake {

template <int Dim>
inline constexpr int kCorners = 1 << Dim;

/// For each cell of `cells` (C order), the positions in the node region
/// `nodes` (C order) of its 2^Dim corner nodes; corner q has node index
/// cell + bit a of q on each axis a. Built once at setup. Throws mpfd::Error
/// if a corner lies outside `nodes`.
template <int Dim>
[[nodiscard]] std::vector<std::size_t> corner_nodes(const IndexBox<Dim>& cells,
                                                    const IndexBox<Dim>& nodes);

/// For each cell of `cells` (C order), Σ_I N_Ic s_I over its corner nodes:
/// s_I = 1/2 per domain face the node lies on (node index 0 or domain_cells
/// on an axis), the share of its volume V_c inside the domain. Built once at setup.
template <int Dim>
[[nodiscard]] std::vector<double> corner_support(const IndexBox<Dim>& cells,
                                                 const Index<Dim>& domain_cells);

/// e_c^int, T (4-3): adds each particle's internal energy (J) to the entry of
/// the cell holding it. `cell_of_particle` has one entry < cell_energy.size()
/// per particle; `cell_energy` is zeroed first. (4-3) as T prints it: equal to
/// the MPM's nodal e_c only where the particles fill the cells evenly.
void sum_internal_energy(std::span<const std::size_t> cell_of_particle,
                         std::span<const double> internal_energy, std::span<double> cell_energy);

/// The MPM data of the `ghost_nodes` export: nodal mass and momentum (node
/// region order) and e_c^int per ghost cell (ghost-cell region order).
template <int Dim>
struct GhostSource {
  std::span<const double> node_mass;
  std::span<const Vec<Dim>> node_momentum;
  std::span<const double> cell_internal_energy;
};

/// Writes ρ, ρv, E of each ghost cell, T (4-1) ... (4-6), for an
/// ApplyRegion{ghost_cells, SET}. `corners` is corner_nodes(ghost cells, ghost
/// nodes), `support` corner_support(ghost cells, domain). Returns the first cell
/// whose interpolated mass is not > 0 (no material there to give the FDM: the
/// caller names it, its position and the time), or nothing if every cell got
/// its values.
template <int Dim>
[[nodiscard]] std::optional<std::size_t> fill_ghost_cells(const GhostSource<Dim>& source,
                                                          std::span<const std::size_t> corners,
                                                          std::span<const double> support,
                                                          double cell_volume,
                                                          const CellOutputs<Dim>& ghost);

}  // namespace mpfd::coupler::handshake
