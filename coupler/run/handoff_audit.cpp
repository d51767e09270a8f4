#include "coupler/run/handoff_audit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

double relative(double a, double b, double scale) {
  const double d = std::abs(a - b);
  return scale > 0.0 ? d / scale : d;
}

}  // namespace

nlohmann::json Conserved::summary() const {
  return {{"mass", mass}, {"momentum", momentum}, {"energy", energy}};
}

std::array<double, 5> Conserved::as_totals() const {
  return {mass, momentum[0], momentum[1], momentum[2], energy};
}

double ConservedError::worst() const {
  return std::max({mass, momentum, energy});
}

nlohmann::json ConservedError::summary() const {
  return {{"mass", mass}, {"momentum", momentum}, {"energy", energy}};
}

Conserved particle_conserved(const handoff::ParticleView& particles) {
  handoff::check_sizes(particles);
  Conserved c;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const double m = particles.mass[p];
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double v = particles.velocity[a][p];
      c.momentum[a] += m * v;
      c.momentum_scale += std::abs(m * v);
      v2 += v * v;
    }
    c.mass += m;
    c.energy += particles.internal_energy[p] + 0.5 * m * v2;
  }
  return c;
}

Conserved cell_conserved(const handoff::ConservedView& cells, double cell_volume) {
  handoff::check_sizes(cells, cells.density.size());
  Conserved c;
  for (std::size_t i = 0; i < cells.density.size(); ++i)
    add_cell(c, cells.density[i],
             {cells.momentum[0][i], cells.momentum[1][i], cells.momentum[2][i]},
             cells.total_energy[i], cell_volume);
  return c;
}

Conserved wire_cell_conserved(std::span<const double> rho, std::span<const double> momentum,
                              std::span<const double> total_energy, double cell_volume) {
  if (momentum.size() != 3 * rho.size() || total_energy.size() != rho.size())
    throw Error("handoff audit: cells need rho [n], momentum [n, 3], E [n]; got " +
                std::to_string(rho.size()) + ", " + std::to_string(momentum.size()) + ", " +
                std::to_string(total_energy.size()) + " values");
  Conserved c;
  for (std::size_t i = 0; i < rho.size(); ++i) {
    c.mass += rho[i] * cell_volume;
    for (int a = 0; a < 3; ++a) {
      const double p = momentum[3 * i + static_cast<std::size_t>(a)] * cell_volume;
      c.momentum[a] += p;
      c.momentum_scale += std::abs(p);
    }
    c.energy += total_energy[i] * cell_volume;
  }
  return c;
}

Conserved profile_conserved(const remap::RadialProfile& profile) {
  const remap::SphericalTotals t = remap::profile_totals(profile);
  return {t.mass, {t.radial_impulse, 0.0, 0.0}, t.energy, t.radial_impulse_magnitude};
}

Conserved from_totals(std::span<const double> totals) {
  if (totals.size() != 5)
    throw Error("handoff audit: FieldImportDone.totals must hold [mass, px, py, pz, E], got " +
                std::to_string(totals.size()) + " values");
  return {totals[0], {totals[1], totals[2], totals[3]}, totals[4], 0.0};
}

ConservedError relative_error(const Conserved& a, const Conserved& b) {
  ConservedError e;
  e.mass = relative(a.mass, b.mass, std::abs(a.mass) > 0.0 ? std::abs(a.mass) : std::abs(b.mass));
  e.energy = relative(a.energy, b.energy,
                      std::abs(a.energy) > 0.0 ? std::abs(a.energy) : std::abs(b.energy));
  const double scale = std::max(a.momentum_scale, b.momentum_scale);
  for (int i = 0; i < 3; ++i)
    e.momentum = std::max(e.momentum, relative(a.momentum[i], b.momentum[i], scale));
  return e;
}

Conserved difference(const Conserved& a, const Conserved& b) {
  Conserved d;
  d.mass = a.mass - b.mass;
  for (int i = 0; i < 3; ++i) d.momentum[i] = a.momentum[i] - b.momentum[i];
  d.energy = a.energy - b.energy;
  d.momentum_scale = a.momentum_scale + b.momentum_scale;
  return d;
}

Conserved sum(const Conserved& a, const Conserved& b) {
  Conserved s;
  s.mass = a.mass + b.mass;
  for (int i = 0; i < 3; ++i) s.momentum[i] = a.momentum[i] + b.momentum[i];
  s.energy = a.energy + b.energy;
  s.momentum_scale = a.momentum_scale + b.momentum_scale;
  return s;
}

}  // namespace mpfd::coupler
