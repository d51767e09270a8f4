// A uniform state handed MPM -> FDM -> MPM comes back unchanged (T §3.2.1,
// §3.2.3): 2^d regular particles per cell, the same mass, velocity and
// internal energy per particle, at the same positions.

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "coupler/handoff/fdm_to_mpm.hpp"
#include "coupler/handoff/mpm_to_fdm.hpp"
#include "tests/unit/coupler/handoff/handoff_test_support.hpp"

namespace mpfd::coupler::handoff {
namespace {

// 2^d particles per cell at x_c +- h/4, written without the kernel's help.
ParticleSet regular_particles(const grid::UniformGrid& grid, double rho, const grid::Vec3& v,
                              double e) {
  ParticleSet p;
  const int dim = grid.dimension();
  const std::size_t per_cell = std::size_t{1} << dim;
  p.resize(per_cell * grid.cell_count());
  std::size_t i = 0;
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const grid::Vec3 centre = grid.cell_center(grid.cell_of_index(c));
    for (std::size_t k = 0; k < per_cell; ++k, ++i) {
      int bit = 0;
      for (int a = 0; a < 3; ++a) {
        p.position[a][i] = centre[a];
        if (!grid.is_active(a)) continue;
        p.position[a][i] += ((k >> bit) & 1 ? 0.25 : -0.25) * grid.spacing()[a];
        ++bit;
      }
      const double m = rho * grid.cell_volume() / static_cast<double>(per_cell);
      p.mass[i] = m;
      for (int a = 0; a < 3; ++a) p.velocity[a][i] = v[a];
      p.internal_energy[i] = m * e;
      p.pressure[i] = 0.0;
      p.material[i] = 0;
    }
  }
  return p;
}

class RoundTrip : public ::testing::TestWithParam<int> {};

TEST_P(RoundTrip, Uniform_state_returns_unchanged_to_round_off) {
  const grid::UniformGrid grid = test::test_grid(GetParam());
  const double rho = 1.225;
  const grid::Vec3 v{30.0, -12.0, 4.0};
  const double e = 2.0685e5;
  const ParticleSet before = regular_particles(grid, rho, v, e);
  const FdmStart start = mpm_to_fdm(grid, before.view());
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    EXPECT_NEAR(start.cells.density[c], rho, 1e-14 * rho) << "cell " << c;

  const std::size_t n = grid.cell_count();
  const std::vector<double> pressure(n, 1.0e5);
  const std::vector<int> material(n, 0);
  const std::vector<double> theta(n, 1.0);
  const std::vector<double> rho_r(n, rho);
  const std::vector<double> e_r(n, e);
  const FdmEnd end{start.cells.view(),  pressure, material, 1, theta, rho_r, e_r,
                   start.tracers.view()};
  const ParticleSet after = fdm_to_mpm(grid, end);

  ASSERT_EQ(after.size(), before.size());
  for (std::size_t p = 0; p < before.size(); ++p) {
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(after.position[a][p], before.position[a][p], 1e-15) << "particle " << p;
      EXPECT_NEAR(after.velocity[a][p], v[a], 1e-12 * 30.0) << "particle " << p;
    }
    EXPECT_NEAR(after.mass[p], before.mass[p], 1e-14 * before.mass[p]) << "particle " << p;
    EXPECT_NEAR(after.internal_energy[p], before.internal_energy[p],
                1e-12 * before.internal_energy[p])
        << "particle " << p;
  }
}

INSTANTIATE_TEST_SUITE_P(Dimensions, RoundTrip, ::testing::Values(1, 2, 3));

}  // namespace
}  // namespace mpfd::coupler::handoff
