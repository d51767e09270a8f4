// shell_material_sums: the per-material sums of a remapped profile and its
// ambient fill, which spherical_to_fdm fits each material's FDM start to.
// Each material's mass is the profile's (and the fill's) to round-off, every
// cell's volumes add up to the cell, and a cell the charge surface cuts starts
// each material at its own shells' density and energy.
#include "coupler/remap/shell_material_sums.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
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

/// Products (material 0) to 0.1 m and shocked air (material 1) to 0.2 m, moving out at
/// u = 300 m/s r / 0.2 m.
struct ChargeInAirProfile {
  std::vector<double> edges, rho, u, e;
  std::vector<int> material;
  ChargeInAirProfile() {
    constexpr int kShells = 40;
    for (int k = 0; k <= kShells; ++k) edges.push_back(kOuterRadius * k / kShells);
    for (int k = 0; k < kShells; ++k) {
      const bool charge = edges[k + 1] <= kChargeRadius;
      rho.push_back(charge ? kProductsDensity : kAirDensity);
      u.push_back(300.0 * 0.5 * (edges[k] + edges[k + 1]) / kOuterRadius);
      e.push_back(charge ? kProductsEnergy : kAirEnergy);
      material.push_back(charge ? 0 : 1);
    }
  }
  [[nodiscard]] RadialProfile view() const { return {edges, rho, u, e, material, {}, {}}; }
};

const handoff::AmbientState kAmbient{
    .material = 1, .density = 1.2, .specific_internal_energy = 2.1e5};

/// The cells the handoff imports: the remapped fields plus the ambient fill (at rest).
handoff::ConservedCells cells_with_fill(const CartesianFields& f) {
  handoff::ConservedCells cells;
  cells.assign(f.density.size());
  for (std::size_t c = 0; c < f.density.size(); ++c) {
    const double rest = std::max(0.0, 1.0 - f.covered_fraction[c]);
    cells.density[c] = f.density[c] + rest * kAmbient.density;
    for (int a = 0; a < 3; ++a) cells.momentum[a][c] = f.momentum[a][c];
    cells.total_energy[c] =
        f.total_energy[c] + rest * kAmbient.density * kAmbient.specific_internal_energy;
  }
  return cells;
}

/// The octant [0, 0.31]^3 m in 40^3 cells (h = 7.75 mm, off the shells' 5 mm edges), the
/// profile centred on its corner.
struct ChargeOctant {
  grid::UniformGrid grid =
      grid::UniformGrid::from_bounds({0, 0, 0}, {0.31, 0.31, 0.31}, {40, 40, 40});
  ChargeInAirProfile profile;
  CartesianFields fields = remap_radial_profile(grid, {0, 0, 0}, profile.view());
  handoff::ConservedCells cells = cells_with_fill(fields);
  handoff::MaterialSums sums =
      shell_material_sums(CartesianFields(fields), grid.cell_volume(), kAmbient, 2);
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
    const double rest = 1.0 - o.fields.covered_fraction[c];
    if (rest > kNegligibleFraction) fill += rest * v_c * kAmbient.density;
    EXPECT_NEAR(o.sums.volume[2 * c] + o.sums.volume[2 * c + 1], v_c, kSumsRoundOff * v_c) << c;
  }
  const double products_mass = kProductsDensity * ball_octant_volume(kChargeRadius);
  const double air_mass =
      kAirDensity * (ball_octant_volume(kOuterRadius) - ball_octant_volume(kChargeRadius)) + fill;
  // Sums over 64 000 cells: their round-off, not one cell's.
  EXPECT_NEAR(products, products_mass, 1e-11 * products_mass);
  EXPECT_NEAR(air, air_mass, 1e-11 * air_mass);
}

// Fitted to the cell (handoff::material_start): each material keeps its own density, and
// both energies take the same share of the remap's kinetic remainder (|p_c|^2 / (2 m_c) is
// below the shells' kinetic energy), so that the materials hold the cell's internal energy.
TEST(ShellMaterialSums, ACellTheChargeSurfaceCutsStartsEachMaterialAtItsOwnState) {
  const ChargeOctant o;
  const double v_c = o.grid.cell_volume();
  const handoff::MaterialStart start = handoff::material_start(o.grid, o.sums, o.cells.view());
  EXPECT_EQ(start.fallback_cells, 0U);
  EXPECT_EQ(start.empty_cells, 0U);
  // Cell (12, 1, 1), centre (0.0969, 0.0116, 0.0116) m at r = 0.098 m: cut by the surface,
  // and inside the air shells, so its air is at the shells' density.
  const std::size_t c = o.grid.cell_index({12, 1, 1});
  ASSERT_GT(o.sums.contributors[2 * c], 0);
  ASSERT_GT(o.sums.contributors[2 * c + 1], 0);
  EXPECT_NEAR(start.volume_fraction[2 * c] * v_c, o.sums.volume[2 * c], kSumsRoundOff * v_c);
  EXPECT_NEAR(start.density[2 * c], kProductsDensity, kSumsRoundOff * kProductsDensity);
  EXPECT_NEAR(start.density[2 * c + 1], kAirDensity, kSumsRoundOff * kAirDensity);
  EXPECT_GT(start.energy[2 * c], kProductsEnergy * (1 + 1e-6));  // the kinetic remainder
  EXPECT_NEAR(start.energy[2 * c] / start.energy[2 * c + 1], kProductsEnergy / kAirEnergy,
              kSumsRoundOff);
  double held = 0.0;
  for (std::size_t r = 0; r < 2; ++r)
    held +=
        start.volume_fraction[2 * c + r] * start.density[2 * c + r] * v_c * start.energy[2 * c + r];
  const double m_c = o.cells.density[c] * v_c;
  double p2 = 0.0;
  for (int a = 0; a < 3; ++a) p2 += std::pow(o.cells.momentum[a][c] * v_c, 2);
  const double internal = o.cells.total_energy[c] * v_c - 0.5 * p2 / m_c;
  EXPECT_NEAR(held, internal, kSumsRoundOff * internal);
}

// A cell the shells cover to round-off has no ambient air in it, and only the cells the
// products' surface cuts are mixed.
TEST(ShellMaterialSums, OnlyTheCellsTheSurfaceCutsHoldTwoMaterials) {
  const ChargeOctant o;
  const double h = o.grid.spacing()[0];
  std::size_t mixed = 0;
  for (std::size_t c = 0; c < o.grid.cell_count(); ++c) {
    const grid::Index3 at = o.grid.cell_of_index(c);
    double near2 = 0.0, far2 = 0.0;  // the cell's nearest and farthest corner from the centre
    for (int a = 0; a < 3; ++a) {
      near2 += std::pow(at[a] * h, 2);
      far2 += std::pow((at[a] + 1) * h, 2);
    }
    const bool cut = std::sqrt(near2) < kChargeRadius && std::sqrt(far2) > kChargeRadius;
    const bool two = o.sums.contributors[2 * c] > 0 && o.sums.contributors[2 * c + 1] > 0;
    EXPECT_EQ(two, cut) << "cell (" << at[0] << ", " << at[1] << ", " << at[2] << ")";
    mixed += two ? 1 : 0;
  }
  EXPECT_GT(mixed, 20U);
}

// A scene with a material the 1D stage does not hold (here a third): its rows are laid
// out among the scene's and stay empty; the profile's rows are the same numbers.
TEST(ShellMaterialSums, RowsOfAMaterialTheProfileLacksStayEmpty) {
  const ChargeOctant o;
  const handoff::MaterialSums three =
      shell_material_sums(CartesianFields(o.fields), o.grid.cell_volume(), kAmbient, 3);
  ASSERT_EQ(three.mass.size(), 3 * o.grid.cell_count());
  for (std::size_t c = 0; c < o.grid.cell_count(); ++c) {
    for (std::size_t r = 0; r < 2; ++r) {
      EXPECT_EQ(three.mass[3 * c + r], o.sums.mass[2 * c + r]) << c;
      EXPECT_EQ(three.volume[3 * c + r], o.sums.volume[2 * c + r]) << c;
      EXPECT_EQ(three.energy[3 * c + r], o.sums.energy[2 * c + r]) << c;
      EXPECT_EQ(three.contributors[3 * c + r], o.sums.contributors[2 * c + r]) << c;
    }
    EXPECT_EQ(three.mass[3 * c + 2], 0.0) << c;
    EXPECT_EQ(three.contributors[3 * c + 2], 0) << c;
  }
}

TEST(ShellMaterialSums, AnAmbientMaterialBeyondTheScenesIsRefused) {
  const ChargeOctant o;
  handoff::AmbientState ambient = kAmbient;
  ambient.material = 2;
  EXPECT_THAT(
      [&] {
        (void)shell_material_sums(CartesianFields(o.fields), o.grid.cell_volume(), ambient, 2);
      },
      ::testing::ThrowsMessage<Error>(::testing::HasSubstr("the ambient is material 2")));
}

}  // namespace
}  // namespace mpfd::coupler::remap
