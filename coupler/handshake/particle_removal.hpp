#pragma once
// MPM -> FDM transport, T §4.2.4, (4-19) ... (4-21): a particle that has left
// the MPM zone (RemoveParticles{"crossed", left_region "mpm_zone"}) is deleted
// from the MPM and its mass, momentum and energy are added to the FDM cell it
// is now in (T: "the FDM cell it moved into"; nearest-cell weighting, as the
// thesis, so each particle's amounts land whole in one cell of `deposit_cells`):
//   Δρ_c = m_p / V_c,  Δ(ρu)_c = m_p u_p / V_c,  ΔE_c = e_p / V_c   T (4-19)...(4-21)
// e_p in (4-21) is read as the particle's total energy e_p^int + ½ m_p |u_p|²
// (E is a total energy density; with e_p^int alone the kinetic energy would
// vanish). The same deposit returns the parcels of injection_flux.hpp to
// their cell k-w. The sums are exact up to round-off: Σ_c Δρ_c V_c = Σ_p m_p.

#include <cstddef>
#include <span>

#include "coupler/handshake/fields.hpp"
#include "coupler/handshake/injection_flux.hpp"

namespace mpfd::coupler::handshake {

/// The position in `deposit` (C order) of the cell holding each particle.
/// Throws mpfd::Error naming the particle and the box if one lies outside it
/// (it moved more than the deposit layers allow: a broken CFL limit).
template <int Dim>
void locate_deposit_cells(std::span<const Vec<Dim>> position, const IndexBox<Dim>& deposit,
                          const CellGeometry<Dim>& geometry, std::span<std::size_t> cell);

/// Momentum m_p u_p and total energy e_p^int + ½ m_p |u_p|² of removed
/// particles, the amounts of T (4-20), (4-21).
template <int Dim>
void particle_amounts(std::span<const double> mass, std::span<const Vec<Dim>> velocity,
                      std::span<const double> internal_energy, std::span<Vec<Dim>> momentum,
                      std::span<double> energy);

/// Adds amount i to cell cell[i] of `add` (the deposit_cells increments of an
/// ApplyRegion{deposit_cells, ADD}; zero them once per step), T (4-19) ... (4-21).
template <int Dim>
void deposit(std::span<const double> mass, std::span<const Vec<Dim>> momentum,
             std::span<const double> energy, std::span<const std::size_t> cell, double cell_volume,
             const CellOutputs<Dim>& add);

}  // namespace mpfd::coupler::handshake
