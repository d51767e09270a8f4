// The 1D spherical MPM's particles as remap shells (shells_from_particles.hpp)
// and the FDM tracers of a remapped profile (radial_tracers.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "common/core/error.hpp"
#include "coupler/remap/radial_tracers.hpp"
#include "coupler/remap/shells_from_particles.hpp"
#include "coupler/remap/spherical_to_cartesian.hpp"

namespace mpfd::coupler::remap {
namespace {

using ::testing::HasSubstr;

// A 1D spherical MPM state after a detonation, as export_profile gives it:
// products (material 0) to 12.4 mm, 2 particles per cell of h = 1 mm, air
// (material 1) to R1 = 50 mm; masses per steradian rho_p r^2 dr, an outgoing
// wave in velocity and energy.
struct SphericalState {
  std::vector<double> radius, mass, velocity, energy, sigma_rr, sigma_tt;
  std::vector<int> material;

  [[nodiscard]] SphericalParticleView view() const {
    return {radius, mass, velocity, energy, material, sigma_rr, sigma_tt};
  }
};

SphericalState detonated_sphere() {
  SphericalState s;
  const double dr = 0.5e-3;
  for (double r = 0.25e-3; r < 0.05; r += dr * (1.0 + 0.2 * std::sin(r * 700.0))) {
    const bool products = r < 0.0124;
    const double rho =
        products ? 400.0 * (1.0 + r / 0.0124) : 1.225 * (1.0 + 3.0 * std::exp(-r / 0.01));
    s.radius.push_back(r);
    s.mass.push_back(rho * r * r * dr);
    s.velocity.push_back(2000.0 * r / 0.05 - (products ? 0.0 : 300.0));
    s.energy.push_back(products ? 3.0e6 * (1.0 - r) : 2.1e5 * (1.0 + r / 0.01));
    s.sigma_rr.push_back(-1e6 * (1.0 + r));
    s.sigma_tt.push_back(-1e6);
    s.material.push_back(products ? 0 : 1);
  }
  return s;
}

TEST(ShellsFromParticles, KeepMassAndEnergyExactly) {
  const SphericalState s = detonated_sphere();
  const RadialShells shells = shells_from_particles(s.view(), 0.05);
  const std::size_t n = s.radius.size();
  ASSERT_EQ(shells.edges.size(), n + 1);
  EXPECT_EQ(shells.edges.front(), 0.0);
  EXPECT_EQ(shells.edges.back(), 0.05);
  for (std::size_t k = 1; k < n; ++k)
    EXPECT_EQ(shells.edges[k], 0.5 * (s.radius[k - 1] + s.radius[k]));
  EXPECT_EQ(shells.material, s.material);
  EXPECT_EQ(shells.radial_stress, s.sigma_rr);

  const SphericalTotals want = particle_totals(s.view());
  const SphericalTotals got = profile_totals(shells.view());
  double impulse_scale = 0.0;  // 4 pi sum |m u|
  for (std::size_t k = 0; k < n; ++k)
    impulse_scale += 4.0 * std::numbers::pi * s.mass[k] * std::abs(s.velocity[k]);
  EXPECT_NEAR(got.mass, want.mass, 1e-14 * want.mass);
  EXPECT_NEAR(got.energy, want.energy, 1e-14 * want.energy);
  EXPECT_NEAR(got.radial_impulse, want.radial_impulse, 1e-14 * impulse_scale);

  // Through the Cartesian remap onto an octant grid holding the whole ball's
  // octant: one eighth of everything, to round-off of the exact overlaps.
  const grid::UniformGrid octant =
      grid::UniformGrid::from_bounds({0, 0, 0}, {0.06, 0.06, 0.06}, {12, 12, 12});
  const RemapTotals inside = totals_inside_grid(octant, {0, 0, 0}, shells.view());
  EXPECT_NEAR(inside.mass, want.mass / 8.0, 1e-12 * want.mass);
  EXPECT_NEAR(inside.energy, want.energy / 8.0, 1e-12 * want.energy);
}

TEST(ShellsFromParticles, RefusesUnorderedParticlesAndAnOuterRadiusInsideThem) {
  SphericalState s = detonated_sphere();
  const auto message = [](const SphericalState& state, double outer) {
    try {
      (void)shells_from_particles(state.view(), outer);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message(s, 0.01), HasSubstr("outer_radius"));
  std::swap(s.radius[3], s.radius[4]);
  EXPECT_THAT(message(s, 0.05), HasSubstr("radius[4]"));
}

// Products to 31 mm (material 0), air to 50 mm (material 1), ambient beyond
// (material 2), about a centre off the grid's nodes.
struct TwoShells {
  std::vector<double> edges{0.0, 0.031, 0.05};
  std::vector<double> density{1000.0, 1.2};
  std::vector<double> velocity{0.0, 100.0};
  std::vector<double> energy{3e6, 2e5};
  std::vector<int> material{0, 1};

  [[nodiscard]] RadialProfile view() const {
    return {edges, density, velocity, energy, material, {}, {}};
  }
};

// Per cell, the fraction of its n^d tracers of each material against the
// remap's exact volume fractions (ambient: 1 - covered_fraction). The
// midpoint rule on n sub-cells per axis: a cell the interface crosses errs
// by at most (interface crossings of a sub-cell line) / (2 n) — 1/n for a
// ball surface — not by 1/n^d, which a flat cut at a quarter sub-cell
// already exceeds (measured worst cell 0.21, 0.085, 0.025 for n = 2, 4, 8);
// summed over the grid the errors cancel to within 1/n^d of each material's
// volume (measured 5.7e-3, 1.7e-3, 7.9e-4). The outer shell (material 1) is not
// the ambient material (2): every cell gets tracers.
TEST(RadialTracers, FractionsMatchRemapWithin1OverNdOverTheGridAndTheMidpointBoundPerCell) {
  const grid::UniformGrid grid =
      grid::UniformGrid::from_bounds({-0.062, -0.058, -0.061}, {0.058, 0.062, 0.059}, {12, 12, 12});
  const grid::Vec3 centre{0.0013, -0.0021, 0.0007};
  const TwoShells shells;
  const CartesianFields exact = remap_radial_profile(grid, centre, shells.view());
  ASSERT_EQ(exact.material_count, 2);
  for (const int n : {2, 4, 8}) {
    const handoff::TracerPoints tracers = radial_tracers(grid, centre, shells.view(), 2, n);
    const std::size_t per_cell = static_cast<std::size_t>(n * n * n);
    std::vector<double> fraction(3 * grid.cell_count(), 0.0);
    std::vector<std::size_t> count(grid.cell_count(), 0);
    for (std::size_t t = 0; t < tracers.size(); ++t) {
      const auto where =
          grid.locate({tracers.position[0][t], tracers.position[1][t], tracers.position[2][t]});
      ASSERT_TRUE(where.has_value());
      const std::size_t c = grid.cell_index(where->cell);
      ++count[c];
      fraction[3 * c + static_cast<std::size_t>(tracers.material[t])] +=
          1.0 / static_cast<double>(per_cell);
    }
    for (std::size_t c = 0; c < grid.cell_count(); ++c)
      ASSERT_EQ(count[c], per_cell) << "cell " << c;
    double worst = 0.0;
    std::array<double, 3> volume_error{};
    std::array<double, 3> volume{};
    for (std::size_t c = 0; c < grid.cell_count(); ++c)
      for (int r = 0; r < 3; ++r) {
        const double theta =
            r < 2 ? exact.volume_fraction[2 * c + r] : 1.0 - exact.covered_fraction[c];
        worst = std::max(worst, std::abs(fraction[3 * c + r] - theta));
        volume_error[r] += (fraction[3 * c + r] - theta) * grid.cell_volume();
        volume[r] += theta * grid.cell_volume();
      }
    std::printf(
        "n = %d: worst cell fraction error %.4f (1/n = %.4f, 1/n^3 = %.4f); material volume errors "
        "%.2e %.2e %.2e\n",
        n, worst, 1.0 / n, 1.0 / (n * n * n), volume_error[0] / volume[0],
        volume_error[1] / volume[1], volume_error[2] / volume[2]);
    EXPECT_LE(worst, 1.0 / n) << "n = " << n;
    // Over the grid, each material's tracer volume is within 1/n^d of the exact one.
    for (int r = 0; r < 3; ++r)
      EXPECT_LE(std::abs(volume_error[r]) / volume[r], 1.0 / (n * n * n))
          << "n = " << n << ", material " << r;
  }
}

// The 1D stage's profile ends in ambient air: only the cells reaching into its
// ball get tracers, and the FDM's fill (nearest seeded cell) makes the others
// that outer shell's material, the ambient one, as the exact remap says.
TEST(RadialTracers, BeyondAnAmbientOuterShellNoCellIsSeeded) {
  const grid::UniformGrid grid =
      grid::UniformGrid::from_bounds({-0.062, -0.058, -0.061}, {0.058, 0.062, 0.059}, {12, 12, 12});
  const grid::Vec3 centre{0.0013, -0.0021, 0.0007};
  TwoShells shells;
  shells.material = {0, 2};  // products inside, then a shell of the ambient air
  const CartesianFields exact = remap_radial_profile(grid, centre, shells.view());
  const handoff::TracerPoints tracers = radial_tracers(grid, centre, shells.view(), 2, 2);
  std::vector<std::size_t> count(grid.cell_count(), 0);
  for (std::size_t t = 0; t < tracers.size(); ++t) {
    const auto where =
        grid.locate({tracers.position[0][t], tracers.position[1][t], tracers.position[2][t]});
    ASSERT_TRUE(where.has_value());
    ++count[grid.cell_index(where->cell)];
  }
  std::size_t empty = 0;
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    if (count[c] == 0) {
      ++empty;
      EXPECT_EQ(exact.covered_fraction[c], 0.0) << "cell " << c << " reaches into the ball";
    } else {
      EXPECT_EQ(count[c], 8U) << "cell " << c;
    }
  }
  // The ball (r = 50 mm) covers ~30 % of the 120 mm cube.
  EXPECT_GT(empty, grid.cell_count() / 2);
  EXPECT_LT(empty, grid.cell_count());
}

TEST(RadialTracers, SitAtTheSubCellCentresLikeTheFdmSeeds) {
  const grid::UniformGrid grid =
      grid::UniformGrid::from_bounds({0, 0, 0}, {0.04, 0.04, 0.01}, {4, 4, 1});
  const TwoShells shells;
  const handoff::TracerPoints tracers = radial_tracers(grid, {0, 0, 0}, shells.view(), 2, 2);
  ASSERT_EQ(tracers.size(), 64u);
  // Cell 0's tracers: (2.5, 2.5), (7.5, 2.5), (2.5, 7.5), (7.5, 7.5) mm, z at the mid-plane.
  EXPECT_NEAR(tracers.position[0][1], 0.0075, 1e-15);
  EXPECT_NEAR(tracers.position[1][2], 0.0075, 1e-15);
  EXPECT_NEAR(tracers.position[2][3], 0.005, 1e-15);
  // Cylindrical in 2D: the cell (3, 3) tracer at (37.5, 37.5) mm is 53 mm out, beyond the profile.
  EXPECT_EQ(tracers.material.back(), 2);
  EXPECT_EQ(tracers.material.front(), 0);
}

}  // namespace
}  // namespace mpfd::coupler::remap
