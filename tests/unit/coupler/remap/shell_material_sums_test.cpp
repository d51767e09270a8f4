// shell_material_sums: the per-material sums of a remapped profile and its
// ambient fill, which spherical_to_fdm fits each material's FDM start to.
// Each material's mass is the profile's (and the fill's) to round-off, every
// cell's volumes add up to the cell, and a cell the charge surface cuts starts
// each material at its own shells' density and energy.
#include "coupler/remap/shell_material_sums.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/core/error.hpp"

namespace mpfd::coupler::remap {
namespace {

constexpr double kSumsRoundOff = 1e-12;
constexpr double kChargeRadius = 0.1, kOuterRadius = 0.2;  // [m]
constexpr double kProductsDensity = 100.0, kProductsEnergy = 2e6;
constexpr double kAirDensity = 3.0, kAirEnergy = 5e5;

/// Products (material 0) to 0.1 m and shocked air (material 1) to 0.2 m, at rest.
struct ChargeInAirProfile {
  std::vector<double> edges, rho, u, e;
  std::vector<int> material;
  ChargeInAirProfile() {
    constexpr int kShells = 40;
    for (int k = 0; k <= kShells; ++k) edges.push_back(kOuterRadius * k / kShells);
    for (int k = 0; k < kShells; ++k) {
      const bool charge = edges[k + 1] <= kChargeRadius;
      rho.push_back(charge ? kProductsDensity : kAirDensity);
      u.push_back(0.0);
      e.push_back(charge ? kProductsEnergy : kAirEnergy);
      material.push_back(charge ? 0 : 1);
    }
  }
  [[nodiscard]] RadialProfile view() const { return {edges, rho, u, e, material, {}, {}}; }
};

const handoff::AmbientState kAmbient{
    .material = 1, .density = 1.2, .specific_internal_energy = 2.1e5};

/// The octant [0, 0.3]^3 m in 12^3 cells, the profile centred on its corner.
struct ChargeOctant {
  grid::UniformGrid grid = grid::UniformGrid::from_bounds({0, 0, 0}, {0.3, 0.3, 0.3}, {12, 12, 12});
  ChargeInAirProfile profile;
  CartesianFields fields = remap_radial_profile(grid, {0, 0, 0}, profile.view());
  handoff::MaterialSums sums = shell_material_sums(fields, grid.cell_volume(), kAmbient, 2);
};

double ball_octant_volume(double r) {
  return std::numbers::pi * r * r * r / 6.0;
}

TEST(ShellMaterialSums, EachMaterialHoldsItsShellsAndTheFillAndEveryCellIsWhole) {
  const ChargeOctant o;
  const double v_c = o.grid.cell_volume();
  double products = 0.0, air = 0.0, fill = 0.0;
  for (std::size_t c = 0; c < o.grid.cell_count(); ++c) {
    products += o.sums.mass[2 * c];
    air += o.sums.mass[2 * c + 1];
    fill += (1.0 - o.fields.covered_fraction[c]) * v_c * kAmbient.density;
    EXPECT_NEAR(o.sums.volume[2 * c] + o.sums.volume[2 * c + 1], v_c, kSumsRoundOff * v_c) << c;
  }
  const double products_mass = kProductsDensity * ball_octant_volume(kChargeRadius);
  const double air_mass =
      kAirDensity * (ball_octant_volume(kOuterRadius) - ball_octant_volume(kChargeRadius)) + fill;
  EXPECT_NEAR(products, products_mass, kSumsRoundOff * products_mass);
  EXPECT_NEAR(air, air_mass, kSumsRoundOff * air_mass);
}

TEST(ShellMaterialSums, ACellTheChargeSurfaceCutsStartsEachMaterialAtItsOwnState) {
  const ChargeOctant o;
  const double v_c = o.grid.cell_volume();
  handoff::ConservedCells cells;
  cells.assign(o.grid.cell_count());
  for (std::size_t c = 0; c < o.grid.cell_count(); ++c) {
    const double mass = o.sums.mass[2 * c] + o.sums.mass[2 * c + 1];
    const double energy = o.sums.energy[2 * c] + o.sums.energy[2 * c + 1];
    cells.density[c] = mass / v_c;
    cells.total_energy[c] = energy / v_c;  // at rest: all of it internal
  }
  const handoff::MaterialStart start = handoff::material_start(o.grid, o.sums, cells.view());
  EXPECT_GT(start.mixed_cells, 20U);
  EXPECT_EQ(start.fallback_cells, 0U);
  EXPECT_EQ(start.empty_cells, 0U);
  // Cell (3, 1, 1), centre (0.0875, 0.0375, 0.0375) m at r = 0.102 m: cut by the surface,
  // and inside the air shells, so its air is at the shells' density.
  const std::size_t c = o.grid.cell_index({3, 1, 1});
  ASSERT_GT(o.sums.contributors[2 * c], 0);
  ASSERT_GT(o.sums.contributors[2 * c + 1], 0);
  EXPECT_NEAR(start.volume_fraction[2 * c] * v_c, o.sums.volume[2 * c], kSumsRoundOff * v_c);
  EXPECT_NEAR(start.density[2 * c], kProductsDensity, kSumsRoundOff * kProductsDensity);
  EXPECT_NEAR(start.density[2 * c + 1], kAirDensity, kSumsRoundOff * kProductsDensity);
  EXPECT_NEAR(start.energy[2 * c], kProductsEnergy, kSumsRoundOff * kProductsEnergy);
  EXPECT_NEAR(start.energy[2 * c + 1], kAirEnergy, kSumsRoundOff * kProductsEnergy);
}

TEST(ShellMaterialSums, AnAmbientMaterialBeyondTheScenesIsRefused) {
  const ChargeOctant o;
  handoff::AmbientState ambient = kAmbient;
  ambient.material = 2;
  EXPECT_THAT([&] { (void)shell_material_sums(o.fields, o.grid.cell_volume(), ambient, 2); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("the ambient is material 2")));
}

}  // namespace
}  // namespace mpfd::coupler::remap
