// AFDMP's MPM -> FDM handoff on the fluid zone only (design §3.5 H1 step 3):
// mpm_to_fdm on the fluid box's grid, embedded into the whole grid, the FSI
// zone filled with the ambient placeholder (coupler/handoff/placeholder.hpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "coupler/handoff/mpm_to_fdm.hpp"
#include "coupler/handoff/placeholder.hpp"
#include "coupler/handoff/sub_grid.hpp"
#include "tests/unit/coupler/handoff/handoff_test_support.hpp"

namespace mpfd::coupler::handoff {
namespace {

bool in_box(const CellBox& box, const grid::Index3& cell) {
  for (int a = 0; a < 3; ++a)
    if (cell[a] < box.lo[a] || cell[a] >= box.hi[a]) return false;
  return true;
}

/// A grid of `dim` active axes, 12 cells along x, and its FSI zone of 4 cell
/// layers along x above (side +1) or below (side -1) the fluid zone.
struct Zones {
  grid::UniformGrid whole;
  CellBox fluid;
  CellBox fsi;
};

Zones zones(int dim, int side) {
  const grid::Index3 cells{12, dim >= 2 ? 5 : 1, dim >= 3 ? 4 : 1};
  const grid::UniformGrid whole({-0.3, 0.1, 0.2},
                                {0.1, dim >= 2 ? 0.2 : 0.05, dim >= 3 ? 0.15 : 0.05}, cells);
  CellBox fluid{{0, 0, 0}, cells};
  CellBox fsi{{0, 0, 0}, cells};
  if (side > 0) {
    fluid.hi[0] = 8;
    fsi.lo[0] = 8;
  } else {
    fluid.lo[0] = 4;
    fsi.hi[0] = 4;
  }
  return {whole, fluid, fsi};
}

class FluidSubGrid : public ::testing::TestWithParam<std::tuple<int, int>> {};

// Particles fill the fluid box up to its FSI face. On the fluid box's grid
// the face's node layer is a boundary layer, its share renormalised
// (grid_stencil.hpp), so all of the particles' mass, momentum and energy land
// in fluid cells and the FSI cells stay exactly zero.
TEST_P(FluidSubGrid, MpmToFdmOnFluidSubGrid_PutsNothingInFsiCellsAndConservesToRoundOff) {
  const auto [dim, side] = GetParam();
  const Zones z = zones(dim, side);
  const grid::UniformGrid fluid = sub_grid(z.whole, z.fluid);
  const ParticleSet particles = test::random_particles(fluid, 400, 7u + dim);
  const FdmStart start = mpm_to_fdm(fluid, particles.view());

  ConservedCells whole;
  whole.assign(z.whole.cell_count());
  embed_cells(z.whole, z.fluid, start.cells.view(), whole);

  for (std::size_t c = 0; c < z.whole.cell_count(); ++c) {
    if (!in_box(z.fsi, z.whole.cell_of_index(c))) continue;
    EXPECT_EQ(whole.density[c], 0.0) << "FSI cell " << c;
    for (int a = 0; a < 3; ++a) EXPECT_EQ(whole.momentum[a][c], 0.0) << "FSI cell " << c;
    EXPECT_EQ(whole.total_energy[c], 0.0) << "FSI cell " << c;
  }
  const test::Totals sent = test::particle_totals(particles.view());
  const test::Totals got = test::cell_totals(z.whole, whole.view());
  double momentum_scale = 0.0;  // sum |m v|: the momentum components cancel
  for (std::size_t p = 0; p < particles.size(); ++p)
    for (int a = 0; a < 3; ++a)
      momentum_scale += std::abs(particles.mass[p] * particles.velocity[a][p]);
  constexpr double kTolerance = 1e-12;
  double worst_momentum = 0.0;
  for (int a = 0; a < 3; ++a)
    worst_momentum = std::max(worst_momentum, std::abs(got.momentum[a] - sent.momentum[a]));
  RecordProperty("relative_error_mass", shortest_text(std::abs(got.mass / sent.mass - 1.0)));
  RecordProperty("relative_error_momentum", shortest_text(worst_momentum / momentum_scale));
  RecordProperty("relative_error_energy", shortest_text(std::abs(got.energy / sent.energy - 1.0)));
  EXPECT_NEAR(got.mass, sent.mass, kTolerance * sent.mass);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(got.momentum[a], sent.momentum[a], kTolerance * momentum_scale) << "axis " << a;
  EXPECT_NEAR(got.energy, sent.energy, kTolerance * sent.energy);
  ASSERT_EQ(start.tracers.size(), particles.size());
  for (std::size_t t = 0; t < start.tracers.size(); ++t) {
    const auto where = z.whole.locate(
        {start.tracers.position[0][t], start.tracers.position[1][t], start.tracers.position[2][t]});
    ASSERT_TRUE(where.has_value());
    EXPECT_TRUE(in_box(z.fluid, where->cell)) << "tracer " << t;
  }
}

INSTANTIATE_TEST_SUITE_P(DimensionsAndSides, FluidSubGrid,
                         ::testing::Combine(::testing::Values(1, 2, 3), ::testing::Values(1, -1)));

constexpr const char* kScene =
    "name: p\ntime: {end: 1.0e-3}\n"
    "domain: {lower: [0, 0, 0], upper: [1.2, 1.0, 0.05], cells: [12, 5, 1]}\n"
    "materials:\n  tnt:\n    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15,"
    " R2: 0.95, omega: 0.3, E0: 6.993e9}\n    explosive: {detonation_velocity: 6930}\n"
    "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
    "initial: {material: air, density: 1.225, pressure: 1.0e5, velocity: [10, -5, 0]}\n"
    "output: {interval: 1.0e-4}\n";

TEST(Placeholder, AmbientStateIsTheSceneInitialWithEFromItsPressure) {
  const AmbientState s = ambient_state(config::parse_scene(kScene, "p.yaml"));
  EXPECT_EQ(s.material, 1);
  EXPECT_EQ(s.density, 1.225);
  EXPECT_EQ(s.velocity, (std::array<double, 3>{10.0, -5.0, 0.0}));
  EXPECT_NEAR(s.specific_internal_energy, 1.0e5 / (0.4 * 1.225), 1e-9);  // p = (gamma - 1) rho e
}

// The FSI cells get the ambient state and tracers_per_axis^d tracers each at
// the sub-cell centres (as fdm_solver's seed_from_materials); the fluid
// cells are left as they were.
TEST(Placeholder, FillsOnlyTheFsiBoxWithAmbientCellsAndRegularTracers) {
  const Zones z = zones(2, 1);
  const AmbientState air{1, 1.225, {10.0, -5.0, 0.0}, 2.0e5};
  ConservedCells cells;
  cells.assign(z.whole.cell_count());
  fill_ambient_cells(z.whole, z.fsi, air, cells);
  for (std::size_t c = 0; c < z.whole.cell_count(); ++c) {
    const bool fsi = in_box(z.fsi, z.whole.cell_of_index(c));
    EXPECT_EQ(cells.density[c], fsi ? 1.225 : 0.0);
    EXPECT_EQ(cells.momentum[1][c], fsi ? -5.0 * 1.225 : 0.0);
    EXPECT_NEAR(cells.total_energy[c], fsi ? 1.225 * (2.0e5 + 62.5) : 0.0, 1e-9);
  }
  TracerPoints tracers;
  tracers.material.push_back(0);  // one already there: appended after it
  for (auto& x : tracers.position) x.push_back(0.05);
  append_regular_tracers(z.whole, z.fsi, 1, 3, tracers);
  ASSERT_EQ(tracers.size(), 1 + z.fsi.count() * 9);
  EXPECT_EQ(tracers.material[0], 0);
  std::vector<int> per_cell(z.whole.cell_count(), 0);
  for (std::size_t t = 1; t < tracers.size(); ++t) {
    EXPECT_EQ(tracers.material[t], 1);
    const grid::Vec3 x{tracers.position[0][t], tracers.position[1][t], tracers.position[2][t]};
    const auto where = z.whole.locate(x);
    ASSERT_TRUE(where.has_value());
    ++per_cell[z.whole.cell_index(where->cell)];
    for (int a = 0; a < 2; ++a) {  // sub-cell centres: local 1/6, 1/2, 5/6
      const double sub = where->local[a] * 3.0 - 0.5;
      EXPECT_NEAR(sub, std::round(sub), 1e-9) << "tracer " << t << " axis " << a;
    }
  }
  for (std::size_t c = 0; c < z.whole.cell_count(); ++c)
    EXPECT_EQ(per_cell[c], in_box(z.fsi, z.whole.cell_of_index(c)) ? 9 : 0) << "cell " << c;
}

}  // namespace
}  // namespace mpfd::coupler::handoff
