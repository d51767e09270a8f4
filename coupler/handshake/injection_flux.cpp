#include "coupler/handshake/injection_flux.hpp"

#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handshake {
namespace {

template <int Dim>
void move_parcel(Parcels<Dim>& pending, std::size_t t, const Amounts<Dim>& returned) {
  returned.mass[t] = pending.mass[t];
  returned.momentum[t] = pending.momentum[t];
  returned.energy[t] = pending.energy[t];
  pending.clear(t);
}

template <int Dim>
void require_amount_lengths(const Amounts<Dim>& amounts, std::size_t n, const char* what) {
  require_length(amounts.mass.size(), n, what, "mass");
  require_length(amounts.momentum.size(), n, what, "momentum");
  require_length(amounts.energy.size(), n, what, "energy");
}

}  // namespace

template <int Dim>
Parcels<Dim>::Parcels(std::size_t face_cells)
    : mass(face_cells, 0.0),
      momentum(face_cells, Vec<Dim>::Zero()),
      energy(face_cells, 0.0),
      volume(face_cells, 0.0),
      travel(face_cells, 0.0) {}

template <int Dim>
void Parcels<Dim>::clear(std::size_t t) {
  mass[t] = 0;
  momentum[t].setZero();
  energy[t] = 0;
  volume[t] = 0;
  travel[t] = 0;
}

template <int Dim>
void accumulate_face_fluxes(const CellStates<Dim>& strip, const StripLayout<Dim>& layout,
                            const CellGeometry<Dim>& geometry, double dt, Parcels<Dim>& pending,
                            const Amounts<Dim>& returned) {
  geometry.check();
  const std::size_t n = layout.face_cells();
  require_lengths(strip, layout.box.count(), "strip cells");
  require_length(pending.size(), n, "pending parcels", "mass");
  require_amount_lengths(returned, n, "returned parcels");
  require(dt > 0, "face fluxes", "dt", dt, "> 0");
  const int axis = layout.face.axis;
  const double area = geometry.face_area(axis);
  for (std::size_t t = 0; t < n; ++t) {
    const std::size_t a = layout.outer[t];
    const std::size_t b = layout.inner[t];
    if (!(strip.rho[a] > 0 && strip.rho[b] > 0))
      throw Error("face fluxes: face cell " + std::to_string(t) +
                  " needs rho > 0 on both sides, got " + shortest_text(strip.rho[a]) + " and " +
                  shortest_text(strip.rho[b]));
    const Vec<Dim> v_a = strip.momentum[a] / strip.rho[a];
    const Vec<Dim> v_b = strip.momentum[b] / strip.rho[b];
    const double rho_e_a = strip.energy[a] - 0.5 * strip.rho[a] * v_a.squaredNorm();
    const double rho_e_b = strip.energy[b] - 0.5 * strip.rho[b] * v_b.squaredNorm();
    if (!(rho_e_a > 0 && rho_e_b > 0))
      throw Error("face fluxes: face cell " + std::to_string(t) +
                  " needs internal energy density > 0 on both sides, got " +
                  shortest_text(rho_e_a) + " and " + shortest_text(rho_e_b));
    const double rho_f = 0.5 * (strip.rho[a] + strip.rho[b]);  // T (4-10)
    const Vec<Dim> v_f = 0.5 * (v_a + v_b);                    // T (4-11)
    const double rho_e_f = 0.5 * (rho_e_a + rho_e_b);          // T (4-12), energy form
    const double inflow = layout.face.side * v_f(axis);        // v_1f into the zone
    if (!(inflow > 0)) {
      move_parcel(pending, t, returned);
      continue;
    }
    const double swept = inflow * area * dt;
    const double mass_flux = rho_f * swept;  // T (4-13)
    pending.mass[t] += mass_flux;
    pending.momentum[t] += mass_flux * v_f;  // T (4-14)
    pending.energy[t] += (rho_e_f + 0.5 * rho_f * v_f.squaredNorm()) * swept;
    pending.volume[t] += swept;
    pending.travel[t] += inflow * dt;
    returned.mass[t] = 0;
    returned.momentum[t].setZero();
    returned.energy[t] = 0;
  }
}

template <int Dim>
void accumulate_crossed_amounts(const CrossedAmounts<Dim>& crossed, const CellStates<Dim>& strip,
                                std::span<const double> pressure, const StripLayout<Dim>& layout,
                                const CellGeometry<Dim>& geometry, double dt, Parcels<Dim>& pending,
                                const Amounts<Dim>& returned) {
  geometry.check();
  const std::size_t n = layout.face_cells();
  require_lengths(strip, layout.box.count(), "strip cells");
  require_length(pressure.size(), layout.box.count(), "strip cells", "pressure");
  require_length(crossed.mass.size(), n, "crossed amounts", "mass");
  require_length(crossed.momentum.size(), n, "crossed amounts", "momentum");
  require_length(crossed.energy.size(), n, "crossed amounts", "energy");
  require_length(pending.size(), n, "pending parcels", "mass");
  require_amount_lengths(returned, n, "returned parcels");
  require(dt > 0, "crossed amounts", "dt", dt, "> 0");
  const int axis = layout.face.axis;
  const double area = geometry.face_area(axis);
  Vec<Dim> normal = Vec<Dim>::Zero();  // into the zone
  normal(axis) = layout.face.side;
  for (std::size_t t = 0; t < n; ++t) {
    const std::size_t a = layout.outer[t];
    const std::size_t b = layout.inner[t];
    if (!(strip.rho[a] > 0 && strip.rho[b] > 0))
      throw Error("crossed amounts: face cell " + std::to_string(t) +
                  " needs rho > 0 on both sides, got " + shortest_text(strip.rho[a]) + " and " +
                  shortest_text(strip.rho[b]));
    const double rho_f = 0.5 * (strip.rho[a] + strip.rho[b]);  // T (4-10)
    const double m = crossed.mass[t];
    const double volume = m / rho_f;
    // The FDM's face flux carries its face pressure's impulse and work; p_f ~ that pressure.
    const double p_f = 0.5 * (pressure[a] + pressure[b]);
    const Vec<Dim> momentum = crossed.momentum[t] - p_f * area * dt * normal;
    const double energy = crossed.energy[t] - p_f * volume;
    if (m > 0) {
      pending.mass[t] += m;
      pending.momentum[t] += momentum;
      pending.energy[t] += energy;
      pending.volume[t] += volume;
      pending.travel[t] += volume / area;
      returned.mass[t] = 0;
      returned.momentum[t].setZero();
      returned.energy[t] = 0;
      // p_f only estimates the face pressure the FDM's flux holds: behind a strong
      // wave (p* far from p_f) the corrected momentum can carry more kinetic energy
      // than the parcel has energy, and T (4-18) would make particles with e < 0.
      // Such a parcel goes back whole to cell a (as where the flow leaves), which
      // keeps every total exact and the particles' energy positive.
      if (!(pending.energy[t] - 0.5 * pending.momentum[t].squaredNorm() / pending.mass[t] > 0))
        move_parcel(pending, t, returned);
      continue;
    }
    if (-m < pending.mass[t]) {
      // Flow back out: the FDM's flux takes back first what still waits in the parcel (the
      // slab next to the face), by its share. Returning the whole parcel at once dumped it into
      // cell k-w at every flow reversal (acoustic case, docs/stability.md: +0.039 Pa in that
      // cell against a 0.007 Pa wave, which then pumped the zone's face).
      const double share = -m / pending.mass[t];
      returned.mass[t] = 0;  // share * M + m, exactly
      returned.momentum[t] = share * pending.momentum[t] + momentum;
      returned.energy[t] = share * pending.energy[t] + energy;
      const double keep = 1 - share;
      pending.mass[t] += m;
      pending.momentum[t] *= keep;
      pending.energy[t] *= keep;
      pending.volume[t] *= keep;
      pending.travel[t] *= keep;
      continue;
    }
    move_parcel(pending, t, returned);
    returned.mass[t] += m;
    returned.momentum[t] += momentum;
    returned.energy[t] += energy;
  }
}

template <int Dim>
void drain_parcels(Parcels<Dim>& pending, const Amounts<Dim>& returned) {
  require_amount_lengths(returned, pending.size(), "returned parcels");
  for (std::size_t t = 0; t < pending.size(); ++t) move_parcel(pending, t, returned);
}

#define MPFD_INSTANTIATE_FLUX(Dim)                                                                 \
  template struct Parcels<Dim>;                                                                    \
  template void accumulate_face_fluxes<Dim>(const CellStates<Dim>&, const StripLayout<Dim>&,       \
                                            const CellGeometry<Dim>&, double, Parcels<Dim>&,       \
                                            const Amounts<Dim>&);                                  \
  template void drain_parcels<Dim>(Parcels<Dim>&, const Amounts<Dim>&);                            \
  template void accumulate_crossed_amounts<Dim>(const CrossedAmounts<Dim>&,                        \
                                                const CellStates<Dim>&, std::span<const double>,   \
                                                const StripLayout<Dim>&, const CellGeometry<Dim>&, \
                                                double, Parcels<Dim>&, const Amounts<Dim>&);
MPFD_INSTANTIATE_FLUX(1)
MPFD_INSTANTIATE_FLUX(2)
MPFD_INSTANTIATE_FLUX(3)
#undef MPFD_INSTANTIATE_FLUX

}  // namespace mpfd::coupler::handshake
