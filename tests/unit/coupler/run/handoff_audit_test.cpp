// The sums a handoff is audited by (coupler/run/handoff_audit.hpp, design §3.6).
#include "coupler/run/handoff_audit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "common/core/error.hpp"
#include "coupler/handoff/fdm_to_mpm.hpp"
#include "coupler/handoff/sub_grid.hpp"

namespace mpfd::coupler {
namespace {

TEST(HandoffAudit, ParticleSumsByHand) {
  handoff::ParticleSet p;
  p.resize(2);
  p.mass = {2.0, 3.0};
  p.velocity[0] = {1.0, -1.0};
  p.velocity[1] = {0.0, 2.0};
  p.internal_energy = {10.0, 20.0};
  const Conserved c = particle_conserved(p.view());
  EXPECT_EQ(c.mass, 5.0);
  EXPECT_EQ(c.momentum[0], -1.0);
  EXPECT_EQ(c.momentum[1], 6.0);
  EXPECT_EQ(c.momentum_scale, 2.0 + 3.0 + 6.0);
  EXPECT_EQ(c.energy, 30.0 + 1.0 + 1.5 * 5.0);
  const auto json = c.summary();
  EXPECT_EQ(json["momentum"][1], 6.0);
  EXPECT_EQ(c.as_totals()[4], c.energy);
}

struct RandomCells {
  grid::UniformGrid grid{{0.0, 0.0, 0.0}, {0.01, 0.02, 0.015}, {5, 4, 3}};
  handoff::ConservedCells cells;
  std::vector<double> pressure;

  RandomCells() {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t n = grid.cell_count();
    cells.assign(n);
    pressure.resize(n);
    for (std::size_t c = 0; c < n; ++c) {
      const double rho = 1.0 + 5.0 * unit(rng);
      cells.density[c] = rho;
      double v2 = 0.0;
      for (int a = 0; a < 3; ++a) {
        const double v = 500.0 * (unit(rng) - 0.5);
        cells.momentum[a][c] = rho * v;
        v2 += v * v;
      }
      cells.total_energy[c] = rho * (2e5 * (1.0 + unit(rng)) + 0.5 * v2);
      pressure[c] = 1e5;
    }
  }
};

// The same cells summed from grid-order component arrays and from the wire's
// [n, 3] in box C order agree to round-off; an FDM -> MPM handoff of them
// agrees with its particles within the audit's 1e-12.
TEST(HandoffAudit, CellsOnTheWireAndTheirParticlesAgree) {
  const RandomCells r;
  const double v = r.grid.cell_volume();
  const Conserved cells = cell_conserved(r.cells.view(), v);
  const std::size_t n = r.grid.cell_count();
  std::vector<double> rho(n), momentum(3 * n), energy(n);
  handoff::grid_to_wire_order(r.grid.cells(), r.cells.density, rho);
  handoff::grid_to_wire_vectors(
      r.grid.cells(), {r.cells.momentum[0], r.cells.momentum[1], r.cells.momentum[2]}, momentum);
  handoff::grid_to_wire_order(r.grid.cells(), r.cells.total_energy, energy);
  const Conserved wire = wire_cell_conserved(rho, momentum, energy, v);
  EXPECT_LE(relative_error(cells, wire).worst(), 1e-14);

  const std::vector<int> material(n, 0);
  const std::vector<double> theta(n, 1.0);
  const std::vector<double> unread(n, 0.0);  // per-material fields: read in mixed cells only
  const handoff::FdmEnd end{r.cells.view(), r.pressure, material, 1, theta, unread, unread, {}};
  const handoff::ParticleSet particles = handoff::fdm_to_mpm(r.grid, end);
  const ConservedError e = relative_error(cells, particle_conserved(particles.view()));
  EXPECT_LE(e.mass, 1e-12);
  EXPECT_LE(e.momentum, 1e-12);
  EXPECT_LE(e.energy, 1e-12);
  EXPECT_EQ(e.summary().size(), 3u);
}

TEST(HandoffAudit, MomentumIsRelativeToTheSumOfMagnitudes) {
  Conserved a{1.0, {1e-3, 0.0, 0.0}, 10.0, 100.0};  // components cancel to 1e-3 of 100
  Conserved b{1.0, {2e-3, 0.0, 0.0}, 10.0, 0.0};    // as FieldImportDone.totals: no scale
  EXPECT_DOUBLE_EQ(relative_error(a, b).momentum, 1e-5);
  EXPECT_DOUBLE_EQ(relative_error(b, a).momentum, 1e-5);
  const Conserved t = from_totals(std::vector<double>{1.0, 2.0, 3.0, 4.0, 5.0});
  EXPECT_EQ(t.momentum[2], 4.0);
  EXPECT_EQ(t.energy, 5.0);
  EXPECT_THROW((void)from_totals(std::vector<double>{1.0}), Error);
  const Conserved d = difference(sum(a, b), b);
  EXPECT_EQ(d.mass, a.mass);
  EXPECT_EQ(d.momentum[0], a.momentum[0]);
}

TEST(HandoffAudit, ProfileSumsAreTheShellsMassRadialImpulseAndEnergy) {
  const std::vector<double> edges{0.0, 1.0, 2.0};
  const std::vector<double> rho{3.0, 1.0};
  const std::vector<double> u{0.0, -10.0};
  const std::vector<double> e{5.0, 7.0};
  const std::vector<int> material{0, 1};
  const Conserved c = profile_conserved({edges, rho, u, e, material, {}, {}});
  const double m0 = 3.0 * 4.0 * std::numbers::pi / 3.0;
  const double m1 = 1.0 * 4.0 * std::numbers::pi / 3.0 * 7.0;
  EXPECT_NEAR(c.mass, m0 + m1, 1e-14 * c.mass);
  EXPECT_NEAR(c.momentum[0], -10.0 * m1, 1e-14 * c.momentum_scale);
  EXPECT_NEAR(c.momentum_scale, 10.0 * m1, 1e-14 * c.momentum_scale);
  EXPECT_NEAR(c.energy, 5.0 * m0 + (7.0 + 50.0) * m1, 1e-14 * c.energy);
}

}  // namespace
}  // namespace mpfd::coupler
