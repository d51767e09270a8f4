#pragma once
// What a handoff moves, summed the same way on both sides (design §3.6): the
// coupler compares what it received, what it sent and the importer's own
// FieldImportDone.totals. Sums of:
//   particles: m, m v, e + m |v|^2 / 2          (e extensive, handoff README reading 2)
//   cells:     rho V, (rho v) V, E V            (T (2-49), V the cell volume)
//   a spherical radial profile: the shells' 4 pi/3 (r_{k+1}^3 - r_k^3) rho_k (...),
//     with the radial impulse sum m u in momentum[0] (the vector momentum of a
//     spherical profile is zero; design §3.5 H1s compares the radial impulse).
// Momentum is compared relative to sum |m v_i| (its components cancel; a
// blast at rest has a total of ~0), mass and energy relative to themselves.

#include <array>
#include <cmath>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <span>

#include "coupler/handoff/particle_fields.hpp"
#include "coupler/remap/radial_profile.hpp"

namespace mpfd::coupler {

struct Conserved {
  double mass = 0.0;                 ///< [kg]
  std::array<double, 3> momentum{};  ///< [kg m/s]
  double energy = 0.0;               ///< total [J]
  double momentum_scale = 0.0;       ///< sum over items and axes of |m v_i| [kg m/s]

  /// {"mass": .., "momentum": [..], "energy": ..} (summary.json, design §3.6).
  [[nodiscard]] nlohmann::json summary() const;
  /// The FieldImportDone.totals order: [mass, px, py, pz, E] (proto README §15).
  [[nodiscard]] std::array<double, 5> as_totals() const;
};

/// Relative differences of two sums of the same thing.
struct ConservedError {
  double mass = 0.0;
  double momentum = 0.0;  ///< max_i |dp_i| / max(scale of either side)
  double energy = 0.0;

  [[nodiscard]] double worst() const;
  [[nodiscard]] nlohmann::json summary() const;
};

/// Particles: velocity components and internal energies [J] per particle.
[[nodiscard]] Conserved particle_conserved(const handoff::ParticleView& particles);
/// Adds one cell of volume `cell_volume` holding rho, rho v and E to `c`
/// (what cell_conserved sums, in its order).
inline void add_cell(Conserved& c, double density, const std::array<double, 3>& momentum,
                     double total_energy, double cell_volume) {
  c.mass += density * cell_volume;
  for (int a = 0; a < 3; ++a) {
    const double p = momentum[a] * cell_volume;
    c.momentum[a] += p;
    c.momentum_scale += std::abs(p);
  }
  c.energy += total_energy * cell_volume;
}
/// Cells of volume `cell_volume`: rho, rho v (three component arrays), E.
[[nodiscard]] Conserved cell_conserved(const handoff::ConservedView& cells, double cell_volume);
/// Cells as on the wire: rho [n], momentum [n, 3] (rho v), E [n]. Throws
/// mpfd::Error on mismatched sizes.
[[nodiscard]] Conserved wire_cell_conserved(std::span<const double> rho,
                                            std::span<const double> momentum,
                                            std::span<const double> total_energy,
                                            double cell_volume);
/// A spherical profile: mass, radial impulse in momentum[0], energy.
[[nodiscard]] Conserved profile_conserved(const remap::RadialProfile& profile);
/// From FieldImportDone.totals [mass, px, py, pz, E]; no momentum scale.
[[nodiscard]] Conserved from_totals(std::span<const double> totals);

/// |a - b| relative to a's mass and energy (or b's, if a's is zero) and to the
/// larger momentum scale (b's may be 0, as from_totals gives).
[[nodiscard]] ConservedError relative_error(const Conserved& a, const Conserved& b);
/// a - b (momentum_scale: the sum of both, an upper bound of the difference's).
[[nodiscard]] Conserved difference(const Conserved& a, const Conserved& b);
[[nodiscard]] Conserved sum(const Conserved& a, const Conserved& b);

}  // namespace mpfd::coupler
