#pragma once
// FDM -> MPM transport across the MPM zone's boundary face, T §4.2.4,
// (4-10) ... (4-14). For face cell t (cells a = k-w outside, b = k-w+1 inside
// the zone, StripLayout), with u_n = side * v_1f the face velocity into the zone:
//   ρ_f = ½(ρ_a + ρ_b),  v_f = ½(v_a + v_b),  (ρe)_f = ½((ρe)_a + (ρe)_b)
//                                                    T (4-10), (4-11), (4-12)
//   f_m = ρ_f u_n A Δt,  f_p = ρ_f v_f u_n A Δt        T (4-13), (4-14)
//   f_E = ((ρe)_f + ½ ρ_f |v_f|²) u_n A Δt            (the energy T leaves to (4-18))
// A = ΔyΔz the face area. (4-12) is used in its EOS-free form: for an ideal gas
// (ρe)_f = p_f / (γ - 1), so f_E's internal part is (4-18)'s p_f m / ((γ-1) ρ_f).
// No pressure work p u A Δt and no pressure impulse p A Δt enter: the MPM gets
// them from the interface force of T (4-9).
// Fluxes are added to a per-face-cell parcel (`Parcels`) that becomes particles
// once heavy enough (particle_injection.hpp). When u_n <= 0 the parcel goes
// back to cell a (`returned`, deposited like a removed particle), so nothing
// waits while the flow leaves the zone. Ledger, per face cell and exact up to
// round-off: Σ fluxes = Σ injected + Σ returned + parcel.

#include <span>
#include <vector>

#include "coupler/handshake/fields.hpp"
#include "coupler/handshake/strip_layout.hpp"

namespace mpfd::coupler::handshake {

/// Amounts (kg, kg m/s, J total energy) per face cell or per particle.
template <int Dim>
struct Amounts {
  std::span<double> mass;
  std::span<Vec<Dim>> momentum;
  std::span<double> energy;
};

/// What has crossed each face cell and is not yet in either solver. Owned by
/// the coupler across steps (and checkpointed with it).
template <int Dim>
struct Parcels {
  std::vector<double> mass;        ///< kg
  std::vector<Vec<Dim>> momentum;  ///< kg m/s
  std::vector<double> energy;      ///< J, internal + kinetic
  std::vector<double> volume;      ///< m^3, Σ f_m / ρ_f (gives the particles' density)
  std::vector<double> travel;      ///< m, Σ u_n Δt (how far the oldest flux has gone)

  explicit Parcels(std::size_t face_cells = 0);
  [[nodiscard]] std::size_t size() const { return mass.size(); }
  /// Empties parcel t.
  void clear(std::size_t t);
};

/// What the FDM put through each face cell in one step toward the zone
/// (protocol v1.1 `coupling_face`, times the face's side): kg, kg m/s, J.
template <int Dim>
struct CrossedAmounts {
  std::span<const double> mass;
  std::span<const Vec<Dim>> momentum;
  std::span<const double> energy;
};

/// The same ledger as accumulate_face_fluxes, from the amounts the FDM moved
/// through the face instead of (4-13), (4-14), so that the mass the FDM loses is
/// exactly what the parcels (or the MPM) gain. Where m = crossed mass > 0 (into
/// the zone) the parcel gets m, P - p_f A Δt n and E - p_f m/ρ_f: the FDM flux
/// holds the pressure impulse and work of its face, which the MPM gets from the
/// interface force (4-9) instead; p_f = ½(p_a + p_b) estimates the face pressure
/// (p_a alone, as (4-9), gave an MPM-part Sod error of 1.67e-2 instead of
/// 1.61e-2, docs/coupler.md); ρ_f is (4-10), volume m/ρ_f, travel m/(ρ_f A). Where m <= 0 the
/// FDM's cell a received the material through its own flux. If the parcel holds more than |m|,
/// that flux took back the parcel's share |m|/M (the material next to the face): the parcel
/// keeps 1 - |m|/M of each amount and `returned` gets the share plus the (negative) advective
/// amounts, zero mass (returning the whole parcel at each flow reversal put it into cell a at
/// once: docs/stability.md, acoustic case). Else the MPM's crossing particles are deposited too:
/// the parcel and those advective amounts go to `returned`, which cancels them. A parcel whose
/// internal energy E - ½|P|²/M is not > 0 after the step's m > 0 (p_f far from the flux's own face
/// pressure, behind a strong wave) also goes to `returned`, whole: T (4-18) would give its
/// particles e < 0. `strip` and `pressure` are the strip_cells of the step's start.
template <int Dim>
void accumulate_crossed_amounts(const CrossedAmounts<Dim>& crossed, const CellStates<Dim>& strip,
                                std::span<const double> pressure, const StripLayout<Dim>& layout,
                                const CellGeometry<Dim>& geometry, double dt, Parcels<Dim>& pending,
                                const Amounts<Dim>& returned);

/// Adds one step's fluxes, T (4-10) ... (4-14), to `pending` where the flow
/// enters the zone, and moves the parcel to `returned` (else zero) where it
/// does not. `strip` is the strip_cells export at t^n, `dt` the step Δt^n.
/// Throws mpfd::Error naming the face cell if a density or the internal energy
/// of a cell is not > 0. (For a solver without v1.1 `face_crossing`.)
template <int Dim>
void accumulate_face_fluxes(const CellStates<Dim>& strip, const StripLayout<Dim>& layout,
                            const CellGeometry<Dim>& geometry, double dt, Parcels<Dim>& pending,
                            const Amounts<Dim>& returned);

/// Moves every parcel to `returned` (the flush before output or checkpoint).
template <int Dim>
void drain_parcels(Parcels<Dim>& pending, const Amounts<Dim>& returned);

}  // namespace mpfd::coupler::handshake
