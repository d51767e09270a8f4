#include "coupler/handoff/fdm_to_mpm.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/coupler/handoff/handoff_test_support.hpp"

namespace mpfd::coupler::handoff {
namespace {

using test::kRoundOff;

// An FDM end state with two materials (per-material arrays [c * 2 + r]):
// random conserved fields, every
// third cell mixed with tracers of both materials, the per-material
// densities off the closure's sum by up to 1 % (the handoff must still
// conserve), the rest single-material with tracers to be discarded.
struct Phase2State {
  ConservedCells cells;
  std::vector<double> pressure;
  std::vector<int> cell_material;
  std::vector<double> theta;
  std::vector<double> rho_r;
  std::vector<double> e_r;
  TracerPoints tracers;

  [[nodiscard]] FdmEnd view() const {
    return {cells.view(), pressure, cell_material, 2, theta, rho_r, e_r, tracers.view()};
  }
};

Phase2State random_state(const grid::UniformGrid& grid, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = grid.cell_count();
  Phase2State s;
  s.cells.assign(n);
  s.pressure.resize(n);
  s.cell_material.resize(n);
  s.theta.assign(2 * n, 0.0);
  s.rho_r.assign(2 * n, 0.0);
  s.e_r.assign(2 * n, 0.0);
  for (std::size_t c = 0; c < n; ++c) {
    const double rho = 1.0 + 10.0 * unit(rng);
    s.cells.density[c] = rho;
    double v2 = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double v = 400.0 * (unit(rng) - 0.5);
      s.cells.momentum[a][c] = rho * v;
      v2 += v * v;
    }
    const double e = 2e5 * (1.0 + unit(rng));
    s.cells.total_energy[c] = rho * (e + 0.5 * v2);
    s.pressure[c] = 1e5 * (1.0 + unit(rng));
    const grid::Vec3 centre = grid.cell_center(grid.cell_of_index(c));
    const auto add_tracer = [&](int material) {
      for (int a = 0; a < 3; ++a)
        s.tracers.position[a].push_back(centre[a] + (unit(rng) - 0.5) * 0.9 * grid.spacing()[a]);
      s.tracers.material.push_back(material);
    };
    if (c % 3 == 0) {
      s.cell_material[c] = kMixedCell;
      const double theta0 = 0.2 + 0.6 * unit(rng);
      s.theta[2 * c] = theta0;
      s.theta[2 * c + 1] = 1.0 - theta0;
      // Products dense, air light; sum rho_r theta_r = rho (1 + 0.01 noise).
      const double rho0 = rho * (1.5 + 0.01 * unit(rng));
      s.rho_r[2 * c] = rho0;
      s.rho_r[2 * c + 1] = (rho - rho0 * theta0) / (1.0 - theta0) > 0.0
                               ? (rho - rho0 * theta0) / (1.0 - theta0)
                               : 0.1 * rho;
      s.e_r[2 * c] = e * 1.3;
      s.e_r[2 * c + 1] = e * 0.8;
      for (int k = 0; k < 3; ++k) add_tracer(0);
      for (int k = 0; k < 2; ++k) add_tracer(1);
    } else {
      s.cell_material[c] = static_cast<int>(c % 2);
      s.theta[2 * c + c % 2] = 1.0;
      add_tracer(s.cell_material[c]);
    }
  }
  return s;
}

class FdmToMpmDimension : public ::testing::TestWithParam<int> {};

TEST_P(FdmToMpmDimension, Conserves_mass_momentum_and_energy_with_mixed_cells) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  const Phase2State state = random_state(grid, 21u + GetParam());
  const ParticleSet particles = fdm_to_mpm(grid, state.view());
  const test::Totals cells = test::cell_totals(grid, state.cells.view());
  double scale = 0.0;
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    for (int a = 0; a < 3; ++a) scale += std::abs(state.cells.momentum[a][c]) * grid.cell_volume();
  test::expect_totals_near(test::particle_totals(particles.view()), cells, scale);
}

TEST_P(FdmToMpmDimension, Single_material_cells_get_2_to_the_d_regular_particles_T_3_18) {
  const int dim = GetParam();
  const grid::UniformGrid grid = test::test_grid(dim);
  Phase2State state = random_state(grid, 4u);
  for (std::size_t c = 0; c < grid.cell_count(); ++c) state.cell_material[c] = 0;
  const ParticleSet particles = fdm_to_mpm(grid, state.view());
  const std::size_t per_cell = std::size_t{1} << dim;
  ASSERT_EQ(particles.size(), per_cell * grid.cell_count());
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const std::size_t c = p / per_cell;
    const grid::Index3 cell = grid.cell_of_index(c);
    const grid::Vec3 centre = grid.cell_center(cell);
    for (int a = 0; a < 3; ++a) {
      const double offset = (particles.position[a][p] - centre[a]) / grid.spacing()[a];
      EXPECT_NEAR(std::abs(offset), grid.is_active(a) ? 0.25 : 0.0, 1e-12) << "axis " << a;
    }
    const auto where =
        grid.locate({particles.position[0][p], particles.position[1][p], particles.position[2][p]});
    ASSERT_TRUE(where.has_value());
    EXPECT_EQ(grid.cell_index(where->cell), c);
    const double m_c = state.cells.density[c] * grid.cell_volume();
    EXPECT_NEAR(particles.mass[p], m_c / static_cast<double>(per_cell), 1e-15 * m_c);  // T (3-14)
    EXPECT_EQ(particles.pressure[p], state.pressure[c]);                               // T (3-17)
  }
}

// The MPM needs particle volumes: V_c / 2^d per regular particle,
// theta_r V_c / n_br per tracer particle with the theta_r normalised (here
// they sum to 1.01 in the mixed cells, a closure off by 1 %), so every cell's
// particles fill exactly its volume.
TEST_P(FdmToMpmDimension, VolumesSumToCellVolume) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  Phase2State state = random_state(grid, 33u + GetParam());
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    if (state.cell_material[c] == kMixedCell) state.theta[2 * c + 1] += 0.01;
  const ParticleSet particles = fdm_to_mpm(grid, state.view());
  std::vector<double> filled(grid.cell_count(), 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const auto where =
        grid.locate({particles.position[0][p], particles.position[1][p], particles.position[2][p]});
    ASSERT_TRUE(where.has_value());
    filled[grid.cell_index(where->cell)] += particles.volume[p];
  }
  const double v_c = grid.cell_volume();
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    EXPECT_NEAR(filled[c], v_c, 1e-15 * v_c) << "cell " << c;
  // Cell 0 is mixed: its 3 tracers of material 0 come first.
  ASSERT_EQ(state.cell_material[0], kMixedCell);
  const double theta0 = state.theta[0] / (state.theta[0] + state.theta[1]);
  EXPECT_NEAR(particles.volume[0], theta0 * v_c / 3.0, 1e-15 * v_c);
}

INSTANTIATE_TEST_SUITE_P(Dimensions, FdmToMpmDimension, ::testing::Values(1, 2, 3));

TEST(FdmToMpm, Mixed_cell_tracers_become_particles_sharing_by_volume_fraction_T_3_19) {
  const grid::UniformGrid grid = test::test_grid(2);
  const Phase2State state = random_state(grid, 8u);
  const ParticleSet particles = fdm_to_mpm(grid, state.view());
  // Cell 0 is mixed, with 3 tracers of material 0 and 2 of material 1: the
  // first 5 particles, at the tracers' positions.
  ASSERT_EQ(state.cell_material[0], kMixedCell);
  double mass0 = 0.0;
  double mass1 = 0.0;
  for (std::size_t p = 0; p < 5; ++p) {
    EXPECT_EQ(particles.position[0][p], state.tracers.position[0][p]);
    EXPECT_EQ(particles.material[p], state.tracers.material[p]);
    (particles.material[p] == 0 ? mass0 : mass1) += particles.mass[p];
  }
  EXPECT_NEAR(mass0 / mass1, state.rho_r[0] * state.theta[0] / (state.rho_r[1] * state.theta[1]),
              1e-13);
  EXPECT_NEAR(mass0 + mass1, state.cells.density[0] * grid.cell_volume(),
              kRoundOff * (mass0 + mass1));
  EXPECT_EQ(particles.mass[0], particles.mass[1]);  // equal shares within a material
}

TEST(FdmToMpm, Material_without_tracers_in_a_mixed_cell_gets_regular_particles) {
  const grid::UniformGrid grid = test::test_grid(3);
  Phase2State state = random_state(grid, 6u);
  // Drop the material-1 tracers of cell 0 (tracers 3 and 4).
  for (int a = 0; a < 3; ++a)
    state.tracers.position[a].erase(state.tracers.position[a].begin() + 3,
                                    state.tracers.position[a].begin() + 5);
  state.tracers.material.erase(state.tracers.material.begin() + 3,
                               state.tracers.material.begin() + 5);
  const ParticleSet particles = fdm_to_mpm(grid, state.view());
  int material1 = 0;
  for (std::size_t p = 0; p < 11; ++p) material1 += particles.material[p] == 1 ? 1 : 0;
  EXPECT_EQ(material1, 8);
  const test::Totals cells = test::cell_totals(grid, state.cells.view());
  EXPECT_NEAR(test::particle_totals(particles.view()).mass, cells.mass, kRoundOff * cells.mass);
}

TEST(FdmToMpm, Wrong_array_size_is_an_error) {
  const grid::UniformGrid grid = test::test_grid(2);
  Phase2State state = random_state(grid, 2u);
  state.pressure.pop_back();
  EXPECT_THROW((void)fdm_to_mpm(grid, state.view()), Error);
}

}  // namespace
}  // namespace mpfd::coupler::handoff
