#pragma once
// Shared by the handoff tests: grids of dimension 1, 2, 3 and random MPM
// particle sets with their totals.

#include <array>
#include <cstddef>
#include <random>

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"

namespace mpfd::coupler::handoff::test {

/// Round-off tolerance of a sum of ~1e3 terms of one sign: 1e-13 relative.
inline constexpr double kRoundOff = 1e-13;

/// A grid of `dim` active axes (4, 3, 5 cells; spacing 0.1, 0.2, 0.15 m;
/// inactive axes 0.05 m thick).
inline grid::UniformGrid test_grid(int dim) {
  const grid::Index3 cells{4, dim >= 2 ? 3 : 1, dim >= 3 ? 5 : 1};
  const grid::Vec3 spacing{0.1, dim >= 2 ? 0.2 : 0.05, dim >= 3 ? 0.15 : 0.05};
  return grid::UniformGrid({-0.2, 0.1, 0.3}, spacing, cells);
}

struct Totals {
  double mass = 0.0;
  std::array<double, 3> momentum{};
  double energy = 0.0;
};

inline Totals particle_totals(const ParticleView& p) {
  Totals t;
  for (std::size_t i = 0; i < p.size(); ++i) {
    t.mass += p.mass[i];
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      t.momentum[a] += p.mass[i] * p.velocity[a][i];
      v2 += p.velocity[a][i] * p.velocity[a][i];
    }
    t.energy += p.internal_energy[i] + 0.5 * p.mass[i] * v2;
  }
  return t;
}

inline Totals cell_totals(const grid::UniformGrid& grid, const ConservedView& c) {
  Totals t;
  const double v = grid.cell_volume();
  for (std::size_t i = 0; i < c.density.size(); ++i) {
    t.mass += c.density[i] * v;
    for (int a = 0; a < 3; ++a) t.momentum[a] += c.momentum[a][i] * v;
    t.energy += c.total_energy[i] * v;
  }
  return t;
}

/// `n` particles uniformly spread over the grid box with random masses,
/// velocities (components in [-300, 300] m/s), energies and materials 0/1.
inline ParticleSet random_particles(const grid::UniformGrid& grid, std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ParticleSet p;
  p.resize(n);
  const grid::Vec3 lo = grid.origin();
  const grid::Vec3 hi = grid.upper();
  for (std::size_t i = 0; i < n; ++i) {
    for (int a = 0; a < 3; ++a) {
      p.position[a][i] = lo[a] + (hi[a] - lo[a]) * (0.999 * unit(rng));
      p.velocity[a][i] = 600.0 * (unit(rng) - 0.5);
    }
    p.mass[i] = 1e-3 * (0.5 + unit(rng));
    p.internal_energy[i] = 200.0 * (0.5 + unit(rng));
    p.pressure[i] = 0.0;
    p.material[i] = unit(rng) < 0.3 ? 1 : 0;
  }
  return p;
}

inline void expect_totals_near(const Totals& got, const Totals& want, double scale_momentum) {
  EXPECT_NEAR(got.mass, want.mass, kRoundOff * want.mass);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(got.momentum[a], want.momentum[a], kRoundOff * scale_momentum) << "axis " << a;
  EXPECT_NEAR(got.energy, want.energy, kRoundOff * want.energy);
}

}  // namespace mpfd::coupler::handoff::test
