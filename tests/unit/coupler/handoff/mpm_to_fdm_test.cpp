#include "coupler/handoff/mpm_to_fdm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/coupler/handoff/handoff_test_support.hpp"

namespace mpfd::coupler::handoff {
namespace {

using test::kRoundOff;

// Scale for momentum round-off: sum_p m_p |v_p| (the momenta cancel).
double momentum_scale(const ParticleView& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    s += p.mass[i] *
         (std::abs(p.velocity[0][i]) + std::abs(p.velocity[1][i]) + std::abs(p.velocity[2][i]));
  return s;
}

class MpmToFdmDimension : public ::testing::TestWithParam<int> {};

TEST_P(MpmToFdmDimension, Conserves_mass_momentum_and_energy_to_round_off) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  const ParticleSet particles = test::random_particles(grid, 2000, 11u + GetParam());
  const FdmStart start = mpm_to_fdm(grid, particles.view());
  test::expect_totals_near(test::cell_totals(grid, start.cells.view()),
                           test::particle_totals(particles.view()),
                           momentum_scale(particles.view()));
}

TEST_P(MpmToFdmDimension, Nodal_mass_equals_particle_mass_T_2_12) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  const ParticleSet particles = test::random_particles(grid, 500, 3u);
  const NodalFields nodes = scatter_to_nodes(grid, particles.view());
  double nodal = 0.0;
  for (const double m : nodes.mass) nodal += m;
  EXPECT_NEAR(nodal, test::particle_totals(particles.view()).mass, kRoundOff * nodal);
}

TEST_P(MpmToFdmDimension, Projection_heat_is_the_lost_kinetic_energy_and_non_negative) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  const ParticleSet particles = test::random_particles(grid, 2000, 5u);
  const FdmStart start = mpm_to_fdm(grid, particles.view());
  double particle_kinetic = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    for (int a = 0; a < 3; ++a)
      particle_kinetic +=
          0.5 * particles.mass[p] * particles.velocity[a][p] * particles.velocity[a][p];
  double cell_kinetic = 0.0;
  const double v = grid.cell_volume();
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    double p2 = 0.0;
    for (int a = 0; a < 3; ++a) p2 += std::pow(start.cells.momentum[a][c] * v, 2);
    cell_kinetic += 0.5 * p2 / (start.cells.density[c] * v);
  }
  EXPECT_GT(start.kinetic_to_internal, 0.0);
  EXPECT_NEAR(start.kinetic_to_internal, particle_kinetic - cell_kinetic,
              kRoundOff * particle_kinetic);
}

TEST_P(MpmToFdmDimension, Uniform_velocity_is_kept_and_makes_no_heat) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  ParticleSet particles = test::random_particles(grid, 1500, 9u);
  const std::array<double, 3> u{120.0, -40.0, 75.0};
  for (std::size_t p = 0; p < particles.size(); ++p)
    for (int a = 0; a < 3; ++a) particles.velocity[a][p] = u[a];
  const FdmStart start = mpm_to_fdm(grid, particles.view());
  double kinetic = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p)
    kinetic += 0.5 * particles.mass[p] * (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  EXPECT_NEAR(start.kinetic_to_internal, 0.0, kRoundOff * kinetic);
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(start.cells.momentum[a][c] / start.cells.density[c], u[a], 1e-12 * 120.0);
}

TEST_P(MpmToFdmDimension, T_3_8_as_printed_loses_exactly_the_projection_heat) {
  // Without nodal kinetic energy (node_mass, node_momentum and
  // cell_internal_energy only) the cells hold E_c = (e_c + |p_c|^2/(2 m_c)) / V_c:
  // the total falls short by kinetic_to_internal of the conservative path.
  const grid::UniformGrid grid = test::test_grid(GetParam());
  const ParticleSet particles = test::random_particles(grid, 2000, 7u);
  NodalFields nodes = scatter_to_nodes(grid, particles.view());
  const std::vector<double> internal = cell_internal_energy(grid, particles.view());
  const FdmCells conservative = cells_from_nodes(grid, nodes, internal);
  nodes.kinetic_energy.clear();
  const FdmCells printed = cells_from_nodes(grid, nodes, internal);
  const double total = test::particle_totals(particles.view()).energy;
  EXPECT_EQ(printed.kinetic_to_internal, 0.0);
  EXPECT_NEAR(test::cell_totals(grid, printed.cells.view()).energy,
              total - conservative.kinetic_to_internal, kRoundOff * total);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, MpmToFdmDimension, ::testing::Values(1, 2, 3));

TEST(MpmToFdm, Particles_become_massless_tracers_with_position_and_material) {
  const grid::UniformGrid grid = test::test_grid(3);
  const ParticleSet particles = test::random_particles(grid, 100, 1u);
  const FdmStart start = mpm_to_fdm(grid, particles.view());
  ASSERT_EQ(start.tracers.size(), particles.size());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    EXPECT_EQ(start.tracers.material[p], particles.material[p]);
    for (int a = 0; a < 3; ++a) EXPECT_EQ(start.tracers.position[a][p], particles.position[a][p]);
  }
}

TEST(MpmToFdm, Single_particle_mass_goes_through_the_nodes_to_the_cells_of_T_3_3) {
  // 1D, 4 cells of 0.1 m: a particle at local 0.25 of cell 1 gives node 1
  // 3/4 and node 2 1/4 of its mass; nodes share 1/2 with each adjacent cell.
  const grid::UniformGrid grid({0.0, 0.0, 0.0}, {0.1, 1.0, 1.0}, {4, 1, 1});
  ParticleSet one;
  one.resize(1);
  one.position = {{{0.125}, {0.5}, {0.5}}};
  one.mass = {8.0};
  one.velocity = {{{0.0}, {0.0}, {0.0}}};
  one.internal_energy = {0.0};
  one.material = {0};
  const FdmStart start = mpm_to_fdm(grid, one.view());
  const double v = grid.cell_volume();
  EXPECT_DOUBLE_EQ(start.cells.density[0] * v, 3.0);
  EXPECT_DOUBLE_EQ(start.cells.density[1] * v, 4.0);
  EXPECT_DOUBLE_EQ(start.cells.density[2] * v, 1.0);
  EXPECT_DOUBLE_EQ(start.cells.density[3] * v, 0.0);
}

TEST(MpmToFdm, Particle_outside_the_grid_is_an_error) {
  const grid::UniformGrid grid = test::test_grid(2);
  ParticleSet particles = test::random_particles(grid, 10, 2u);
  particles.position[0][4] = 5.0;
  EXPECT_THROW((void)mpm_to_fdm(grid, particles.view()), Error);
}

}  // namespace
}  // namespace mpfd::coupler::handoff
