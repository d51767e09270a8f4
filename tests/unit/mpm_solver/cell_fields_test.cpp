#include "mpm_solver/cell_fields.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

config::Scene two_slabs() {
  auto scene = testing::gas_scene(
      "[1, 0.5, 0.1]", "[10, 5, 1]",
      "bodies:\n" +
          testing::gas_body("left", "[0, 0, 0]", "[0.4, 0.5, 0.1]", 1.5, 2.0e5, "[30, 0, 0]") +
          testing::gas_body("right", "[0.4, 0, 0]", "[0.8, 0.5, 0.1]", 0.5, 1.0e5, "[-10, 5, 0]"));
  scene.output.fields = {config::Field::density, config::Field::velocity, config::Field::pressure,
                         config::Field::volume_fraction, config::Field::material};
  return scene;
}

const io::FieldView& field(const std::vector<io::FieldView>& views, const std::string& name) {
  for (const auto& v : views)
    if (v.name == name) return v;
  throw std::runtime_error("no field " + name);
}

TEST(CellFields, BinnedCellsCarryTheParticlesMassAndMomentumExactly) {
  const auto scene = two_slabs();
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  for (int i = 0; i < 20; ++i) solver.advance(solver.stable_dt());
  CellFields cells(scene, solver.grid());
  const auto views = cells.views(solver);
  const auto& rho = field(views, "density").components[0];
  const auto& vel = field(views, "velocity").components;
  const double cell_volume = solver.grid().cell_volume();
  double mass = 0.0;
  std::array<double, 3> momentum{};
  for (std::size_t c = 0; c < rho.size(); ++c) {
    mass += rho[c] * cell_volume;
    for (int a = 0; a < 3; ++a) momentum[a] += rho[c] * cell_volume * vel[a][c];
  }
  const MpmTotals totals = solver.totals();
  EXPECT_NEAR(mass, totals.mass, 1e-14 * totals.mass);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(momentum[a], totals.momentum[a], 1e-12 * totals.mass * 30);
}

TEST(CellFields, FreshSlabsReadTheirOwnStateAndEmptyCellsReadNothing) {
  const auto scene = two_slabs();
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  CellFields cells(scene, solver.grid());
  const auto views = cells.views(solver);
  const auto& rho = field(views, "density").components[0];
  const auto& p = field(views, "pressure").components[0];
  const auto& vx = field(views, "velocity").components[0];
  const auto& theta = field(views, "volume_fraction_gas").components[0];
  const auto& material = field(views, "material").components[0];
  const auto& grid = solver.grid();
  for (int j = 0; j < 5; ++j) {
    const std::size_t left = grid.cell_index(1, j, 0), right = grid.cell_index(6, j, 0),
                      empty = grid.cell_index(9, j, 0);
    EXPECT_NEAR(rho[left], 1.5, 1e-12);
    EXPECT_NEAR(p[left], 2.0e5, 1e-6);
    EXPECT_NEAR(vx[left], 30.0, 1e-12);
    EXPECT_NEAR(rho[right], 0.5, 1e-12);
    EXPECT_NEAR(vx[right], -10.0, 1e-12);
    EXPECT_NEAR(theta[left], 1.0, 1e-14);
    EXPECT_EQ(material[left], 0.0);
    EXPECT_EQ(rho[empty], 0.0);
    EXPECT_EQ(theta[empty], 0.0);
    EXPECT_EQ(material[empty], -1.0);
  }
}

TEST(GaugeCells, AGaugeReadsTheCellItStandsIn) {
  const auto scene = two_slabs();
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  for (int i = 0; i < 10; ++i) solver.advance(solver.stable_dt());
  const std::vector<grid::Vec3> at = {{0.15, 0.25, 0.05}, {0.65, 0.45, 0.05}, {0.95, 0.05, 0.05}};
  GaugeCells gauges(solver.grid(), at);
  std::vector<double> out(5 * at.size());
  gauges.sample(solver.particles(), out);
  CellFields cells(scene, solver.grid());
  const auto views = cells.views(solver);
  const auto& rho = field(views, "density").components[0];
  const auto& p = field(views, "pressure").components[0];
  const auto& vel = field(views, "velocity").components;
  for (std::size_t g = 0; g < at.size(); ++g) {
    const std::size_t c = cell_holding(solver.grid(), at[g][0], at[g][1], at[g][2]);
    EXPECT_DOUBLE_EQ(out[5 * g + 0], rho[c]);
    EXPECT_DOUBLE_EQ(out[5 * g + 1], p[c]);
    for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(out[5 * g + 2 + a], vel[a][c]);
  }
  EXPECT_GT(out[0], 0.0);   // inside the (by now rarefied) dense slab
  EXPECT_EQ(out[10], 0.0);  // beyond the slabs: empty
}

}  // namespace
}  // namespace mpfd::mpm
