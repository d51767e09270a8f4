#pragma once
// The FDM's share of the MPM interface nodes, T §4.2.3, (4-7) ... (4-9). The
// nodes on the MPM zone's boundary face (region `interface_nodes`) see the
// particles on the zone's side, and, on the other side, the FDM cells k-w
// (outer layer of `strip_cells`) as particles of volume V_c at their centres:
//   m_I += Σ_c ρ_c N_Ic V_c                                  T (4-7), 2nd term
//   p_I += Σ_c ρ_c V_c v_c N_Ic = Σ_c (ρv)_c V_c N_Ic         T (4-8), 2nd term
//   f_I^int += Σ_c ∇N_Ic p_c V_c                             T (4-9), 2nd term
// c runs over the 2^(Dim-1) outer cells that have node I as a corner (T:
// "the FDM cells adjacent to the node"; cell k-w+1 is covered by particles).
// At a cell centre N_Ic = 2^-Dim and ∂N_Ic/∂x_a = s_a / (Δx_a 2^(Dim-1)),
// s_a = +1 if the node is on the cell's upper side along a, else -1. The FDM
// term is the MPM internal force -∇N σ V of a fluid particle, σ = -p I. The
// MPM adds these to its own P2G sums before (2-13) (protocol: ADD). With a
// uGIMP/cpGIMP MPM the node layer one cell outside the face (`outer_nodes`)
// gets the same terms from cells k-w and k-w-1 (`beyond_cells`), each with
// volume V_c: a uGIMP particle near the face reaches that layer too.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "coupler/handshake/fields.hpp"
#include "coupler/handshake/strip_layout.hpp"

namespace mpfd::coupler::handshake {

template <int Dim>
inline constexpr int kFaceCorners = 1 << (Dim - 1);

/// Per interface node (C order of the `interface_nodes` box): the face cells
/// t whose outer cell has the node as a corner, slot q meaning the node is on
/// the cell's upper side along the b-th transverse axis iff bit b of q is set;
/// -1 where that cell is not in the strip (the strip's lateral edge).
template <int Dim>
struct InterfaceStencil {
  std::vector<std::array<std::int64_t, kFaceCorners<Dim>>> cells;
};

/// Builds the stencil of `nodes` (a one-node-thick box on the face layer of
/// `strip`). Throws mpfd::Error if the box is not on the face.
template <int Dim>
[[nodiscard]] InterfaceStencil<Dim> make_interface_stencil(const StripLayout<Dim>& strip,
                                                           const IndexBox<Dim>& nodes);

/// The stencil of `nodes` (a one-node-thick box) on the node layer one cell
/// outside the face, the far corners of the cells k-w: the layer a uGIMP particle
/// within its half-width of the face reaches (see outer_node_terms). Slots as in
/// InterfaceStencil. Throws mpfd::Error if the box is not on that layer.
template <int Dim>
[[nodiscard]] InterfaceStencil<Dim> make_outer_node_stencil(const StripLayout<Dim>& strip,
                                                            const IndexBox<Dim>& nodes);

/// The second terms of T (4-7) ... (4-9) for each interface node, written to
/// `add` (an ApplyRegion{interface_nodes, ADD}) from the strip's exported
/// states and pressure (strip order). The force (4-9) uses p - reference_pressure
/// [Pa]: the MPM zone's particles leave solver.mpm.reference_pressure out of their
/// stress (docs/mpm.md), and the FDM cells standing in for particles must too, or
/// a uniform state would push the face nodes. `force_volume`, per face cell,
/// replaces V_c in (4-9) for that face cell's outer cell (empty: V_c, T as
/// printed; the coupler passes the MPM's mass in cell k-w+1 over ρ_c, see
/// face_push_volume).
template <int Dim>
void interface_node_terms(const CellStates<Dim>& strip, std::span<const double> strip_pressure,
                          double reference_pressure, const StripLayout<Dim>& layout,
                          const InterfaceStencil<Dim>& stencil, const CellGeometry<Dim>& geometry,
                          const NodeOutputs<Dim>& add, std::span<const double> force_volume = {});

/// T (4-7) ... (4-9) for the node layer outside the face, written to `add`.
/// With linear shapes no particle of the zone reaches it; a uGIMP particle of
/// half-width a (grid units) does once it lies within a of the face (injected
/// particles, ~u Δt from the face, nearly always), and without the FDM there
/// that node holds only the particle's sliver of mass and its own stress: it
/// flies off and the particle expands as into a vacuum. The FDM's cells are the
/// material there, so the layer gets what it gets at any node: the cells k-w
/// (`strip`'s outer cells) and k-w-1 (`beyond`, one per face cell) as particles
/// of volume V_c at their centres, N_Ic = 2^-Dim. Both push with V_c (a uniform
/// pressure leaves the node at rest; face_push_volume is the face node's balance
/// against the zone's particles). A cell-sized uGIMP particle (a = 1/2) at a cell
/// centre has exactly these linear weights, so this is also the uGIMP P2G of the
/// FDM cells; a = 1/2 or less reaches no node farther out.
template <int Dim>
void outer_node_terms(const CellStates<Dim>& strip, std::span<const double> strip_pressure,
                      const CellStates<Dim>& beyond, std::span<const double> beyond_pressure,
                      double reference_pressure, const StripLayout<Dim>& layout,
                      const InterfaceStencil<Dim>& stencil, const CellGeometry<Dim>& geometry,
                      const NodeOutputs<Dim>& add);

/// The volume of the FDM cell k-w in (4-9) that makes it push on the face nodes
/// as the MPM's own particles would (a departure from T, docs/coupler.md,
/// "FDM push on the interface nodes"): an MPM particle set of mass m at
/// density ρ pushes with p m / ρ, whatever its compression; V_c (T) pushes
/// with p V_c, more than the zone's particles next to the face resist with
/// once they are compressed (their mass is fixed, the FDM cell's grows). So
/// per face cell V = m_t / ρ_outer, m_t the MPM's fluid particles' mass in
/// cell k-w+1 (region face_particles), plus the volume V_s of its solid
/// particles: a solid resists with its stress on its own volume, and its mass
/// at the fluid's density would be thousands of cell volumes. V_c =
/// `cell_volume` where that cell holds no particle. Writes `volume` (one per
/// face cell).
template <int Dim>
void face_push_volume(std::span<const double> face_mass, std::span<const double> solid_volume,
                      std::span<const double> strip_rho, const StripLayout<Dim>& layout,
                      double cell_volume, std::span<double> volume);

}  // namespace mpfd::coupler::handshake
