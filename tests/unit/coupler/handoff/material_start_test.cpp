// Each material's own start state at the MPM -> FDM handoff (material_start.hpp).

#include "coupler/handoff/material_start.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/core/error.hpp"
#include "coupler/handoff/mpm_to_fdm.hpp"
#include "tests/unit/coupler/handoff/handoff_test_support.hpp"

namespace mpfd::coupler::handoff {
namespace {

constexpr int kProducts = 0;
constexpr int kAir = 1;

/// 2D grid of 4 x 3 cells (0.1 x 0.2 x 0.05 m, V_c = 1e-3 m^3). Cell (1, 1)
/// holds two hot dense product particles and two cold air particles; cell
/// (2, 1) one air particle; every other cell none.
struct MixedScene {
  grid::UniformGrid grid = test::test_grid(2);
  ParticleSet particles;
  std::vector<double> volume;
  std::size_t mixed = 0;
  std::size_t air_only = 0;
  std::size_t empty = 0;

  MixedScene() {
    const grid::Vec3 lo = grid.origin();
    const auto point = [&](int i, int j, double fx, double fy) {
      return grid::Vec3{lo[0] + (i + fx) * 0.1, lo[1] + (j + fy) * 0.2, lo[2] + 0.025};
    };
    // products: rho 1000 kg/m^3, e 4 MJ/kg; air: rho 1.2 kg/m^3, e 0.2 MJ/kg
    add(point(1, 1, 0.25, 0.25), kProducts, 0.1, 1e-4, 4.0e6, {120.0, -40.0});
    add(point(1, 1, 0.75, 0.25), kProducts, 0.1, 1e-4, 4.0e6, {80.0, 30.0});
    add(point(1, 1, 0.25, 0.75), kAir, 3.6e-4, 3e-4, 2.0e5, {-60.0, 10.0});
    add(point(1, 1, 0.75, 0.75), kAir, 3.6e-4, 3e-4, 2.0e5, {15.0, 90.0});
    add(point(2, 1, 0.5, 0.5), kAir, 1.2e-3, 1e-3, 2.0e5, {5.0, -5.0});
    mixed = grid.cell_index(1, 1, 0);
    air_only = grid.cell_index(2, 1, 0);
    empty = grid.cell_index(0, 0, 0);
  }
  void add(const grid::Vec3& x, int material, double mass, double v, double e,
           std::array<double, 2> velocity) {
    const std::size_t p = particles.size();
    particles.resize(p + 1);
    for (int a = 0; a < 3; ++a) particles.position[a][p] = x[a];
    particles.velocity[0][p] = velocity[0];
    particles.velocity[1][p] = velocity[1];
    particles.velocity[2][p] = 0.0;
    particles.mass[p] = mass;
    particles.internal_energy[p] = mass * e;
    particles.material[p] = material;
    volume.push_back(v);
  }
  [[nodiscard]] MaterialStart start(const ConservedCells& cells) const {
    return material_start(grid, particles.view(), volume, cells.view(), 2);
  }
};

/// e_c [J/kg] of a cell as the FDM reads it.
double cell_energy(const ConservedCells& cells, std::size_t c) {
  double m2 = 0.0;
  for (int a = 0; a < 3; ++a) m2 += cells.momentum[a][c] * cells.momentum[a][c];
  return (cells.total_energy[c] - 0.5 * m2 / cells.density[c]) / cells.density[c];
}

std::size_t at(std::size_t c, int r) {
  return 2 * c + static_cast<std::size_t>(r);
}

TEST(MaterialStart, MixedCellGetsEachMaterialsOwnStateScaledToTheCell) {
  const MixedScene s;
  const FdmStart fdm = mpm_to_fdm(s.grid, s.particles.view());
  const MaterialStart start = s.start(fdm.cells);
  const std::size_t c = s.mixed;
  const double v_c = s.grid.cell_volume();
  const double rho_c = fdm.cells.density[c];
  const double e_c = cell_energy(fdm.cells, c);
  // theta_r = V_r / sum V, T (3-23) with the particles' volumes.
  EXPECT_NEAR(start.volume_fraction[at(c, kProducts)], 0.25, 1e-15);
  EXPECT_NEAR(start.volume_fraction[at(c, kAir)], 0.75, 1e-15);
  const double theta_p = start.volume_fraction[at(c, kProducts)];
  const double theta_a = start.volume_fraction[at(c, kAir)];
  const double rho_p = start.density[at(c, kProducts)];
  const double rho_a = start.density[at(c, kAir)];
  const double e_p = start.energy[at(c, kProducts)];
  const double e_a = start.energy[at(c, kAir)];
  // T (3-28) with the cell's density of T (3-3), (3-6).
  EXPECT_NEAR(theta_p * rho_p + theta_a * rho_a, rho_c, 1e-14 * rho_c);
  // The cell's internal energy, kinetic remainder included, is the materials'.
  EXPECT_NEAR((theta_p * rho_p * e_p + theta_a * rho_a * e_a) * v_c, rho_c * e_c * v_c,
              1e-13 * rho_c * e_c * v_c);
  // Each keeps the particles' ratio: rho 1000 : 1.2 and e 4 MJ : 0.2 MJ.
  EXPECT_NEAR(rho_p / rho_a, 1000.0 / 1.2, 1e-12 * 1000.0 / 1.2);
  EXPECT_NEAR(e_p / e_a, 20.0, 1e-12 * 20.0);
  // Not the cell average the old rule started both from: the products hold
  // 99.6 % of the mass, so e_p is just above e_c and the air 20 times colder.
  EXPECT_GT(e_p, e_c);
  EXPECT_LT(e_a, 0.1 * e_c);
  EXPECT_GT(rho_p, 3.0 * rho_c);
  EXPECT_LT(rho_a, 0.1 * rho_c);
  EXPECT_EQ(start.mixed_cells, 1u);
  EXPECT_EQ(start.fallback_cells, 0u);
}

TEST(MaterialStart, SingleMaterialCellGetsTheCellsStateAndEmptyCellsNone) {
  const MixedScene s;
  const FdmStart fdm = mpm_to_fdm(s.grid, s.particles.view());
  const MaterialStart start = s.start(fdm.cells);
  const std::size_t c = s.air_only;
  EXPECT_EQ(start.volume_fraction[at(c, kAir)], 1.0);
  EXPECT_EQ(start.density[at(c, kAir)], fdm.cells.density[c]);
  EXPECT_EQ(start.energy[at(c, kAir)], cell_energy(fdm.cells, c));
  EXPECT_EQ(start.volume_fraction[at(c, kProducts)], 0.0);
  ASSERT_GT(fdm.cells.density[s.empty], 0.0);  // mass from the nodes, but no particle
  for (const int r : {kProducts, kAir}) {
    EXPECT_EQ(start.volume_fraction[at(s.empty, r)], 0.0);
    EXPECT_EQ(start.density[at(s.empty, r)], 0.0);
    EXPECT_EQ(start.energy[at(s.empty, r)], 0.0);
  }
  EXPECT_EQ(start.empty_cells, s.grid.cell_count() - 2);
}

TEST(MaterialStart, MixedCellWithoutAPositiveEnergyOrVolumeFallsBackToTheCellsState) {
  for (const bool zero_energy : {true, false}) {
    MixedScene s;
    if (zero_energy)
      s.particles.internal_energy[2] = s.particles.internal_energy[3] = 0.0;  // the air's
    else
      s.volume[0] = s.volume[1] = 0.0;  // the products'
    const FdmStart fdm = mpm_to_fdm(s.grid, s.particles.view());
    const MaterialStart start = s.start(fdm.cells);
    for (const int r : {kProducts, kAir}) {
      EXPECT_EQ(start.volume_fraction[at(s.mixed, r)], 0.0) << zero_energy;
      EXPECT_EQ(start.density[at(s.mixed, r)], 0.0);
      EXPECT_EQ(start.energy[at(s.mixed, r)], 0.0);
    }
    EXPECT_EQ(start.mixed_cells, 1u);
    EXPECT_EQ(start.fallback_cells, 1u);
  }
}

TEST(MaterialStart, MixedCellWithNonPositiveCellEnergyFallsBack) {
  MixedScene s;
  FdmStart fdm = mpm_to_fdm(s.grid, s.particles.view());
  fdm.cells.total_energy[s.mixed] = 0.0;  // U_c < 0 with the cell's momentum
  const MaterialStart start = s.start(fdm.cells);
  EXPECT_EQ(start.volume_fraction[at(s.mixed, kProducts)], 0.0);
  EXPECT_EQ(start.fallback_cells, 1u);
}

TEST(MaterialStart, RefusesParticlesOutsideTheGridUnknownMaterialsAndSizeMismatch) {
  const MixedScene s;
  const FdmStart fdm = mpm_to_fdm(s.grid, s.particles.view());
  {
    MixedScene bad;
    bad.particles.position[0][0] = -5.0;
    EXPECT_THROW((void)bad.start(fdm.cells), Error);
  }
  {
    MixedScene bad;
    bad.particles.material[4] = 2;
    EXPECT_THROW((void)bad.start(fdm.cells), Error);
  }
  {
    MixedScene bad;
    bad.volume.pop_back();
    EXPECT_THROW((void)bad.start(fdm.cells), Error);
  }
}

TEST(MaterialStart, LeavesTheCellsAndTheirTotalsAsMpmToFdmMadeThem) {
  const grid::UniformGrid grid = test::test_grid(3);
  const ParticleSet particles = test::random_particles(grid, 2000, 17u);
  const std::vector<double> volume(particles.size(), 1e-6);
  const FdmStart fdm = mpm_to_fdm(grid, particles.view());
  const MaterialStart start = material_start(grid, particles.view(), volume, fdm.cells.view(), 2);
  EXPECT_GT(start.mixed_cells, 0u);
  // Every mixed cell's materials hold the cell's mass and internal energy.
  const double v_c = grid.cell_volume();
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const double theta0 = start.volume_fraction[at(c, 0)];
    const double theta1 = start.volume_fraction[at(c, 1)];
    if (theta0 <= 0.0 || theta1 <= 0.0) continue;
    const double mass = (theta0 * start.density[at(c, 0)] + theta1 * start.density[at(c, 1)]) * v_c;
    EXPECT_NEAR(mass, fdm.cells.density[c] * v_c, 1e-14 * mass) << "cell " << c;
    const double internal = (theta0 * start.density[at(c, 0)] * start.energy[at(c, 0)] +
                             theta1 * start.density[at(c, 1)] * start.energy[at(c, 1)]) *
                            v_c;
    const double cell_internal = fdm.cells.density[c] * cell_energy(fdm.cells, c) * v_c;
    EXPECT_NEAR(internal, cell_internal, 1e-13 * cell_internal) << "cell " << c;
  }
}

}  // namespace
}  // namespace mpfd::coupler::handoff
