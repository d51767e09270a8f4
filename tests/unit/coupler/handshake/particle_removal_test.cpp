#include "coupler/handshake/particle_removal.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/coupler/handshake/handshake_test_support.hpp"

namespace mpfd::coupler::handshake {
namespace {

using test::Dimensions;

constexpr double kRemovalTol = 1e-12;  // relative round-off of sums over 500 particles

template <class D>
class ParticleRemoval : public ::testing::Test {};
TYPED_TEST_SUITE(ParticleRemoval, Dimensions);

// 500 particles that left the zone anywhere in a 2-cell-deep deposit layer:
// the FDM cells gain, to round-off, their total mass, momentum and energy
// (internal + kinetic), T (4-19) ... (4-21), each in the cell holding it.
TYPED_TEST(ParticleRemoval, Deposit_conserves_mass_momentum_energy) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  auto box = test::cube<Dim>(2, 6);
  box.lo[0] = 8;
  box.hi[0] = 10;
  std::mt19937 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = 500;
  std::vector<Vec<Dim>> position(n), velocity(n);
  std::vector<double> mass(n), internal(n);
  for (std::size_t p = 0; p < n; ++p) {
    for (int a = 0; a < Dim; ++a) {
      const double lo = g.origin(a) + static_cast<double>(box.lo[a]) * g.spacing(a);
      position[p](a) =
          lo + unit(random) * static_cast<double>(box.hi[a] - box.lo[a]) * g.spacing(a);
      velocity[p](a) = 400 * (unit(random) - 0.5);
    }
    mass[p] = 1e-6 * (1 + unit(random));
    internal[p] = 0.3 * (1 + unit(random));
  }
  std::vector<std::size_t> cell(n);
  locate_deposit_cells<Dim>(position, box, g, cell);
  std::vector<Vec<Dim>> momentum(n);
  std::vector<double> energy(n);
  particle_amounts<Dim>(mass, velocity, internal, momentum, energy);
  std::vector<double> d_rho(box.count(), 0.0), d_energy(box.count(), 0.0);
  std::vector<Vec<Dim>> d_momentum(box.count(), Vec<Dim>::Zero());
  deposit<Dim>(mass, momentum, energy, cell, g.cell_volume, {d_rho, d_momentum, d_energy});

  double m_in = 0, e_in = 0, m_out = 0, e_out = 0;
  Vec<Dim> p_in = Vec<Dim>::Zero(), p_out = Vec<Dim>::Zero();
  for (std::size_t p = 0; p < n; ++p) {
    m_in += mass[p];
    p_in += mass[p] * velocity[p];
    e_in += internal[p] + 0.5 * mass[p] * velocity[p].squaredNorm();
    // The cell holds the particle.
    const Vec<Dim> lower = g.lower_corner(box.at(cell[p]));
    for (int a = 0; a < Dim; ++a) {
      EXPECT_GE(position[p](a), lower(a));
      EXPECT_LT(position[p](a), lower(a) + g.spacing(a));
    }
  }
  for (std::size_t c = 0; c < box.count(); ++c) {
    m_out += d_rho[c] * g.cell_volume;
    p_out += d_momentum[c] * g.cell_volume;
    e_out += d_energy[c] * g.cell_volume;
  }
  EXPECT_NEAR(m_out, m_in, kRemovalTol * m_in);
  EXPECT_LE((p_out - p_in).norm(), kRemovalTol * m_in * 200);
  EXPECT_NEAR(e_out, e_in, kRemovalTol * e_in);
}

// T (4-19) ... (4-21) by hand: one particle into a cell in state (ρ, ρu, E).
TEST(ParticleRemoval2D, One_particle_updates_its_cell_as_4_19_to_4_21) {
  const CellGeometry<2> g{{0.0, 0.0}, {0.5, 0.25}, 0.125};
  const IndexBox<2> box{{0, 0}, {2, 2}};
  const std::vector<Vec<2>> position{{0.7, 0.1}};  // cell (1, 0): position 2 in C order
  std::vector<std::size_t> cell(1);
  locate_deposit_cells<2>(position, box, g, cell);
  ASSERT_EQ(cell[0], 2u);
  const std::vector<double> mass{0.25}, internal{3.0};
  const std::vector<Vec<2>> velocity{{2.0, -4.0}};
  std::vector<Vec<2>> momentum(1);
  std::vector<double> energy(1);
  particle_amounts<2>(mass, velocity, internal, momentum, energy);
  std::vector<double> rho(4, 2.0), e(4, 10.0);
  std::vector<Vec<2>> rho_u(4, Vec<2>(1.0, 1.0));
  deposit<2>(mass, momentum, energy, cell, g.cell_volume, {rho, rho_u, e});
  EXPECT_DOUBLE_EQ(rho[2], (2.0 * 0.125 + 0.25) / 0.125);             // T (4-19)
  EXPECT_DOUBLE_EQ(rho_u[2](0), (1.0 * 0.125 + 0.25 * 2.0) / 0.125);  // T (4-20)
  EXPECT_DOUBLE_EQ(rho_u[2](1), (1.0 * 0.125 - 0.25 * 4.0) / 0.125);
  EXPECT_DOUBLE_EQ(e[2], (10.0 * 0.125 + 3.0 + 0.5 * 0.25 * 20.0) / 0.125);  // T (4-21)
  EXPECT_EQ(rho[0], 2.0);
}

TEST(ParticleRemoval1D, Particle_outside_the_deposit_cells_is_refused) {
  const CellGeometry<1> g{Vec<1>(0.0), Vec<1>(1.0), 1.0};
  const std::vector<Vec<1>> position{Vec<1>(3.5)};
  std::vector<std::size_t> cell(1);
  EXPECT_THROW(locate_deposit_cells<1>(position, IndexBox<1>{{0}, {3}}, g, cell), Error);
}

}  // namespace
}  // namespace mpfd::coupler::handshake
