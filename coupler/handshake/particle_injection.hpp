#pragma once
// New MPM particles from the FDM inflow, T §4.2.4, (4-15) ... (4-18), made from
// the parcels of injection_flux.hpp in the first MPM cell (k-w+1) of each face
// cell. For a parcel of mass M, momentum P, energy E, volume V:
//   s = 4 ceil(M / (4 m_e))      T (4-15) rounded up to a multiple of 4
//   m_p = M / s                  T (4-16)
//   v_p = P / M,  e_p^int = (E - ½|P|²/M) / s,  V_p = V / s      T (4-18), see below
// m_e is the mass of the zone's own particles. Minimum-mass rule: a parcel
// becomes particles only once M >= 4 m_min, else it waits (and keeps
// accumulating); so m_p >= min(m_min, m_e / 2) and m_p <= m_e (both as
// raised for a dense parcel, below).
// Dense inflow: with m_e fixed, a parcel k times denser than the zone's seeding
// becomes k times more particles per volume (V6: detonation products at ~100x
// the air's density gave 2.16 M particles, slower than pure MPM). A rule with
// min_particle_volume V_min raises m_e, and m_min with it, to ρ_parcel V_min
// for such parcels: they make no more particles per volume than a parcel of
// density m_e / V_min (within the rounding of T (4-15) above), and T's aim, no
// large mass jump between a new particle and its neighbours, still holds, the
// neighbours having come in at about the same density.
// e_p^int: for one step's parcel of an ideal gas, (E - ½ M v_f²)/s =
// p_f m_p / ((γ-1) ρ_f), T (4-18) at the face state; for a parcel of several
// steps the kinetic energy of their velocity differences becomes internal
// energy (Jensen: e_p^int >= Σ of the parts' internal energies > 0).
// Layout ("placed evenly in the cell", T): 2 positions per transverse axis, at
// ¼ and ¾ of the cell, and L = s / 2^(Dim-1) layers along the normal, at the
// midpoints of L equal slices of the slab from the face to d = min(Σ u_n Δt, Δx)
// into the cell (T (4-17): the farthest particle is about v Δt from the face;
// normal component only, so every particle stays inside its cell). So 1D has
// s layers, 2D 2 x s/2, 3D 2 x 2 x s/4.

#include <cstddef>
#include <span>

#include "coupler/handshake/injection_flux.hpp"

namespace mpfd::coupler::handshake {

/// A multiple of this many particles is created at once (T (4-15): "a multiple of 4").
inline constexpr std::size_t kInjectionGroup = 4;

struct InjectionRule {
  double reference_mass = 0;       ///< m_e of T (4-15), kg: mass of the zone's particles
  double min_particle_mass = 0;    ///< m_min, kg, in (0, m_e]: no lighter particle is made
  double min_particle_volume = 0;  ///< V_min, m^3: no smaller particle is made; 0: no bound

  /// Throws mpfd::Error unless 0 < min_particle_mass <= reference_mass and V_min >= 0.
  void check() const;
};

/// s of T (4-15) for a parcel of mass `mass` and volume `volume`, rounded up to
/// a multiple of 4; 0 while mass < 4 m_min (both raised for a dense parcel).
[[nodiscard]] std::size_t particle_count(double mass, double volume, const InjectionRule& rule);

/// s per face cell into `count`; returns Σ s (the size of the next batch).
template <int Dim>
std::size_t count_new_particles(const Parcels<Dim>& pending, const InjectionRule& rule,
                                std::span<std::size_t> count);

/// The batch of InjectParticles (group "injected"); the coupler adds ids and
/// the material of the zone's fluid. `face_cell` names each particle's parcel.
template <int Dim>
struct NewParticles {
  std::span<Vec<Dim>> position;
  std::span<Vec<Dim>> velocity;
  std::span<double> mass;
  std::span<double> volume;
  std::span<double> internal_energy;
  std::span<std::size_t> face_cell;
};

/// Turns each parcel t with count[t] > 0 into count[t] particles, T (4-16) ...
/// (4-18), written in face-cell order, and subtracts exactly what they carry
/// from the parcel (leaving its round-off residue). `out` holds Σ count entries.
template <int Dim>
void create_particles(Parcels<Dim>& pending, std::span<const std::size_t> count,
                      const StripLayout<Dim>& layout, const CellGeometry<Dim>& geometry,
                      const NewParticles<Dim>& out);

}  // namespace mpfd::coupler::handshake
