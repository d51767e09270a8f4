// S step (4): the remapped Cartesian field discretised by particles. The
// 1D TNT/water profile goes through remap_radial_profile and then
// handoff::fdm_to_mpm (mixed cells at the charge surface have no tracers, so
// each material gets regular particles); mass and energy of the 1D shells
// arrive in the particles to round-off.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "coupler/handoff/fdm_to_mpm.hpp"
#include "coupler/remap/spherical_to_cartesian.hpp"

namespace mpfd::coupler {
namespace {

TEST(RemapToParticles, TNT_sphere_in_water_keeps_mass_and_energy_to_round_off) {
  const int shells = 90;
  std::vector<double> edges, rho, u, e;
  std::vector<int> material;
  for (int k = 0; k <= shells; ++k) edges.push_back(0.45 * k / shells);
  double mass = 0.0;
  double energy = 0.0;
  for (int k = 0; k < shells; ++k) {
    const double r = 0.5 * (edges[k] + edges[k + 1]);
    const bool charge = r < 0.1;
    rho.push_back(charge ? 1630.0 : 1000.0 + 200.0 * std::exp(-r / 0.1));
    u.push_back(charge ? 2000.0 * r : 150.0 * 0.1 / r);
    e.push_back(charge ? 4.29e6 : 5e3);
    material.push_back(charge ? 0 : 1);
    const double v =
        4.0 / 3.0 * std::numbers::pi * (std::pow(edges[k + 1], 3) - std::pow(edges[k], 3));
    mass += rho.back() * v;
    energy += rho.back() * v * (e.back() + 0.5 * u.back() * u.back());
  }
  const remap::RadialProfile profile{edges, rho, u, e, material, {}, {}};
  const grid::UniformGrid grid =
      grid::UniformGrid::from_bounds({-0.5, -0.5, -0.5}, {0.5, 0.5, 0.5}, {20, 20, 20});
  const remap::CartesianFields f = remap::remap_radial_profile(grid, {0, 0, 0}, profile);

  const std::size_t n = grid.cell_count();
  const double volume = grid.cell_volume();
  std::vector<int> cell_material(n, 1);
  std::vector<double> rho_r(2 * n, 0.0);
  std::vector<double> e_r(2 * n, 0.0);
  const std::vector<double> pressure(n, 1e5);
  std::size_t mixed = 0;
  for (std::size_t c = 0; c < n; ++c) {
    int present = 0;
    for (std::size_t r = 0; r < 2; ++r) {
      const std::size_t at = c * 2 + r;
      if (f.volume_fraction[at] <= 0.0) continue;
      ++present;
      cell_material[c] = static_cast<int>(r);
      rho_r[at] = f.material_mass[at] / (f.volume_fraction[at] * volume);
      e_r[at] = f.material_internal_energy[at] / f.material_mass[at];
    }
    if (present == 2) {
      cell_material[c] = handoff::kMixedCell;
      ++mixed;
    }
  }
  EXPECT_GT(mixed, 0u);
  const handoff::TracerPoints no_tracers;
  const handoff::FdmEnd end{
      {f.density, {f.momentum[0], f.momentum[1], f.momentum[2]}, f.total_energy},
      pressure,
      cell_material,
      2,
      f.volume_fraction,
      rho_r,
      e_r,
      no_tracers.view()};
  const handoff::ParticleSet particles = handoff::fdm_to_mpm(grid, end);

  double particle_mass = 0.0;
  double particle_energy = 0.0;
  double charge_mass = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    particle_mass += particles.mass[p];
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) v2 += particles.velocity[a][p] * particles.velocity[a][p];
    particle_energy += particles.internal_energy[p] + 0.5 * particles.mass[p] * v2;
    if (particles.material[p] == 0) charge_mass += particles.mass[p];
  }
  EXPECT_NEAR(particle_mass, mass, 1e-13 * mass);
  EXPECT_NEAR(particle_energy, energy, 1e-13 * energy);
  // The charge: shells below r = 0.1 m (10 of 90 shells of 5 mm).
  EXPECT_NEAR(charge_mass, 1630.0 * 4.0 / 3.0 * std::numbers::pi * 1e-3, 1e-3 * charge_mass);
}

}  // namespace
}  // namespace mpfd::coupler
