#include "coupler/handshake/particle_injection.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handshake {

void InjectionRule::check() const {
  require(reference_mass > 0, "particle injection", "reference_mass", reference_mass, "> 0");
  if (!(min_particle_mass > 0 && min_particle_mass <= reference_mass))  // text only on failure
    require(false, "particle injection", "min_particle_mass", min_particle_mass,
            "in (0, reference_mass = " + shortest_text(reference_mass) + "]");
  require(min_particle_volume >= 0, "particle injection", "min_particle_volume",
          min_particle_volume, ">= 0");
}

std::size_t particle_count(double mass, double volume, const InjectionRule& rule) {
  const auto group = static_cast<double>(kInjectionGroup);
  // The dense-inflow bound of the header: m_e and m_min scaled to ρ V_min.
  const double scale =
      volume > 0 ? std::max(1.0, mass / volume * rule.min_particle_volume / rule.reference_mass)
                 : 1.0;
  if (!(mass >= group * scale * rule.min_particle_mass)) return 0;
  // T (4-15), then up to a multiple of 4: ceil(M / m_e) <= s < M / m_e + 4.
  const double groups = std::ceil(mass / (group * scale * rule.reference_mass));
  if (!(groups <= 1e9))  // also NaN: no parcel of a sane run asks for billions of particles
    throw Error("particle injection: a parcel of " + shortest_text(mass) + " kg asks for " +
                shortest_text(group * groups) + " particles of reference mass " +
                shortest_text(scale * rule.reference_mass) + " kg");
  return kInjectionGroup * static_cast<std::size_t>(groups);
}

template <int Dim>
std::size_t count_new_particles(const Parcels<Dim>& pending, const InjectionRule& rule,
                                std::span<std::size_t> count) {
  rule.check();
  require_length(count.size(), pending.size(), "particle injection", "count");
  std::size_t total = 0;
  for (std::size_t t = 0; t < pending.size(); ++t) {
    count[t] = particle_count(pending.mass[t], pending.volume[t], rule);
    total += count[t];
  }
  return total;
}

template <int Dim>
void create_particles(Parcels<Dim>& pending, std::span<const std::size_t> count,
                      const StripLayout<Dim>& layout, const CellGeometry<Dim>& geometry,
                      const NewParticles<Dim>& out) {
  geometry.check();
  require_length(count.size(), pending.size(), "particle injection", "count");
  require_length(layout.face_cells(), pending.size(), "particle injection", "strip face cells");
  std::size_t total = 0;
  for (const std::size_t s : count) total += s;
  const char* what = "injected particles";
  require_length(out.position.size(), total, what, "position");
  require_length(out.velocity.size(), total, what, "velocity");
  require_length(out.mass.size(), total, what, "mass");
  require_length(out.volume.size(), total, what, "volume");
  require_length(out.internal_energy.size(), total, what, "internal_energy");
  require_length(out.face_cell.size(), total, what, "face_cell");
  const int axis = layout.face.axis;
  const double width = geometry.spacing(axis);
  constexpr std::size_t transverse = std::size_t{1} << (Dim - 1);
  std::size_t p = 0;
  for (std::size_t t = 0; t < pending.size(); ++t) {
    const std::size_t s = count[t];
    if (s == 0) continue;
    if (s % kInjectionGroup != 0 || !(pending.mass[t] > 0))
      throw Error("particle injection: face cell " + std::to_string(t) + " asks for " +
                  std::to_string(s) + " particles from a parcel of " +
                  shortest_text(pending.mass[t]) + " kg; the count must be a multiple of 4 of a " +
                  "parcel with mass > 0");
    const double parcel_mass = pending.mass[t];
    const Vec<Dim> velocity = pending.momentum[t] / parcel_mass;
    const auto ds = static_cast<double>(s);
    const double mass = parcel_mass / ds;  // T (4-16)
    const double internal_energy =
        (pending.energy[t] - 0.5 * pending.momentum[t].dot(velocity)) / ds;  // T (4-18)
    const double volume = pending.volume[t] / ds;
    const double depth = std::min(pending.travel[t], width);  // T (4-17), inside the cell
    const std::size_t layers = s / transverse;
    const Vec<Dim> corner = geometry.lower_corner(layout.inner_cell[t]);
    for (std::size_t layer = 0; layer < layers; ++layer) {
      const double from_face =
          (static_cast<double>(layer) + 0.5) * depth / static_cast<double>(layers);
      for (std::size_t slot = 0; slot < transverse; ++slot, ++p) {
        Vec<Dim> x;
        int b = 0;
        for (int a = 0; a < Dim; ++a) {
          if (a == axis) {
            x(a) = layout.face.side > 0 ? corner(a) + from_face : corner(a) + width - from_face;
          } else {
            x(a) = corner(a) + (((slot >> b) & 1) != 0 ? 0.75 : 0.25) * geometry.spacing(a);
            ++b;
          }
        }
        out.position[p] = x;
        out.velocity[p] = velocity;
        out.mass[p] = mass;
        out.volume[p] = volume;
        out.internal_energy[p] = internal_energy;
        out.face_cell[p] = t;
        pending.mass[t] -= mass;
        pending.momentum[t] -= mass * velocity;
        pending.energy[t] -= internal_energy + 0.5 * mass * velocity.squaredNorm();
        pending.volume[t] -= volume;
      }
    }
    pending.travel[t] = 0;
  }
}

#define MPFD_INSTANTIATE_INJECTION(Dim)                                                    \
  template std::size_t count_new_particles<Dim>(const Parcels<Dim>&, const InjectionRule&, \
                                                std::span<std::size_t>);                   \
  template void create_particles<Dim>(Parcels<Dim>&, std::span<const std::size_t>,         \
                                      const StripLayout<Dim>&, const CellGeometry<Dim>&,   \
                                      const NewParticles<Dim>&);
MPFD_INSTANTIATE_INJECTION(1)
MPFD_INSTANTIATE_INJECTION(2)
MPFD_INSTANTIATE_INJECTION(3)
#undef MPFD_INSTANTIATE_INJECTION

}  // namespace mpfd::coupler::handshake
