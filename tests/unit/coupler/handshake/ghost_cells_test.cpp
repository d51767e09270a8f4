#include "coupler/handshake/ghost_cells.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/coupler/handshake/handshake_test_support.hpp"

namespace mpfd::coupler::handshake {
namespace {

using test::Dimensions;

// Round-off of a few dozen operations on O(1) relative quantities.
constexpr double kTol = 1e-13;

template <class D>
class GhostCells : public ::testing::Test {};
TYPED_TEST_SUITE(GhostCells, Dimensions);

// A uniform MPM state (air at 1.2 kg/m^3, 120 m/s, 2.07e5 J/kg) mapped to the
// nodes by the MPM's own P2G gives ghost cells in exactly that state, T (4-1)...(4-6).
TYPED_TEST(GhostCells, Uniform_MPM_state_is_reproduced_to_round_off) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  const double rho = 1.2;
  const double e = 2.07e5;
  const Vec<Dim> v = test::some_velocity<Dim>();
  const auto particles = test::uniform_particles<Dim>(test::cube<Dim>(0, 6), g, rho, v, e);
  const auto ghost = test::cube<Dim>(2, 4);
  const auto nodes = test::cube<Dim>(2, 5);
  const auto node_data = test::particles_to_nodes<Dim>(particles, 0.0, nodes, g);

  std::vector<std::size_t> cell_of_particle;
  std::vector<double> energy_in_ghost;
  for (std::size_t p = 0; p < particles.mass.size(); ++p) {
    Index<Dim> cell{};
    for (int a = 0; a < Dim; ++a)
      cell[a] = static_cast<std::int64_t>((particles.position[p](a) - g.origin(a)) / g.spacing(a));
    if (!ghost.contains(cell)) continue;
    cell_of_particle.push_back(ghost.flat(cell));
    energy_in_ghost.push_back(particles.internal_energy[p]);
  }
  std::vector<double> cell_energy(ghost.count());
  sum_internal_energy(cell_of_particle, energy_in_ghost, cell_energy);  // T (4-3)

  const auto corners = corner_nodes(ghost, nodes);
  const std::vector<double> support(ghost.count(), 1.0);  // no corner on a domain face
  std::vector<double> out_rho(ghost.count());
  std::vector<Vec<Dim>> out_momentum(ghost.count());
  std::vector<double> out_energy(ghost.count());
  EXPECT_FALSE(fill_ghost_cells<Dim>({node_data.mass, node_data.momentum, cell_energy}, corners,
                                     support, g.cell_volume, {out_rho, out_momentum, out_energy}));
  const double energy = rho * (e + 0.5 * v.squaredNorm());
  for (std::size_t c = 0; c < ghost.count(); ++c) {
    EXPECT_NEAR(out_rho[c], rho, kTol * rho) << "cell " << c;
    EXPECT_LE((out_momentum[c] - rho * v).norm(), kTol * rho * v.norm()) << "cell " << c;
    EXPECT_NEAR(out_energy[c], energy, kTol * energy) << "cell " << c;
  }
}

// Ghost cells along the domain's faces (a wall across the coupling face): the corner
// nodes on a face hold only the half of their volume inside the domain. With the
// MPM's e_c = Σ N_Ic e_I (the support of (4-1), mpm_solver serve) a uniform state
// is reproduced in every cell; dividing by V_c instead gave the cells along one
// face 3/4 of the density in 2D (9/16 in a corner) at the right pressure.
TYPED_TEST(GhostCells, Uniform_state_is_reproduced_next_to_the_domain_faces) {
  constexpr int Dim = TypeParam::value;
  const auto g = test::test_geometry<Dim>();
  const double rho = 1.2;
  const double e = 2.07e5;
  const Vec<Dim> v = test::some_velocity<Dim>();
  const auto particles = test::uniform_particles<Dim>(test::cube<Dim>(0, 6), g, rho, v, e);
  const auto ghost = test::cube<Dim>(0, 6);  // every cell of the 6^Dim domain
  const auto nodes = test::cube<Dim>(0, 7);
  const auto node_data = test::particles_to_nodes<Dim>(particles, 0.0, nodes, g);
  const auto corners = corner_nodes(ghost, nodes);
  Index<Dim> domain{};
  domain.fill(6);
  const auto support = corner_support<Dim>(ghost, domain);
  std::vector<double> cell_energy(ghost.count());  // e_I = e m_I here (uniform e)
  for (std::size_t c = 0; c < ghost.count(); ++c) {
    double m_c = 0;
    for (int q = 0; q < kCorners<Dim>; ++q)
      m_c += node_data.mass[corners[c * kCorners<Dim> + q]] / kCorners<Dim>;
    cell_energy[c] = e * m_c;
  }
  std::vector<double> out_rho(ghost.count());
  std::vector<Vec<Dim>> out_momentum(ghost.count());
  std::vector<double> out_energy(ghost.count());
  EXPECT_FALSE(fill_ghost_cells<Dim>({node_data.mass, node_data.momentum, cell_energy}, corners,
                                     support, g.cell_volume, {out_rho, out_momentum, out_energy}));
  const double energy = rho * (e + 0.5 * v.squaredNorm());
  for (std::size_t c = 0; c < ghost.count(); ++c) {
    EXPECT_NEAR(out_rho[c], rho, kTol * rho) << "cell " << c;
    EXPECT_LE((out_momentum[c] - rho * v).norm(), kTol * rho * v.norm()) << "cell " << c;
    EXPECT_NEAR(out_energy[c], energy, kTol * energy) << "cell " << c;
  }
}

TEST(GhostCells2D, Corner_support_halves_per_domain_face) {
  // 4 x 3 cells: an inner cell, one on the face y = 3, one in the corner (0, 0).
  const IndexBox<2> cells{{0, 0}, {4, 3}};
  const auto support = corner_support<2>(cells, Index<2>{4, 3});
  EXPECT_DOUBLE_EQ(support[cells.flat({1, 1})], 1.0);
  EXPECT_DOUBLE_EQ(support[cells.flat({2, 2})], 0.75);
  EXPECT_DOUBLE_EQ(support[cells.flat({0, 0})], 0.5625);
}

// T (4-1), (4-2), (4-6) evaluated by hand on one 2D cell with unequal nodes.
TEST(GhostCells2D, Matches_hand_evaluation_of_4_1_to_4_6) {
  const std::vector<double> mass{1.0, 2.0, 3.0, 6.0};
  const std::vector<Vec<2>> momentum{{4.0, 0.0}, {0.0, 8.0}, {-4.0, 4.0}, {8.0, 4.0}};
  const std::vector<double> internal{10.0};
  IndexBox<2> cell{{5, 7}, {6, 8}};
  IndexBox<2> nodes{{5, 7}, {7, 9}};
  const auto corners = corner_nodes(cell, nodes);
  // C order of the node box is (i, j) with j fastest; corner q has bit 0 on i.
  EXPECT_EQ(corners, (std::vector<std::size_t>{0, 2, 1, 3}));
  double rho = 0;
  Vec<2> m{};
  double energy = 0;
  const std::vector<double> support{1.0};
  EXPECT_FALSE(fill_ghost_cells<2>({mass, momentum, internal}, corners, support, 0.5,
                                   {{&rho, 1}, {&m, 1}, {&energy, 1}}));
  // m_c = (1 + 2 + 3 + 6) / 4 = 3, p_c = (8, 16) / 4 = (2, 4), |v_c|^2 = 20/9.
  EXPECT_DOUBLE_EQ(rho, 3.0 / 0.5);
  EXPECT_DOUBLE_EQ(m(0), 2.0 / 0.5);
  EXPECT_DOUBLE_EQ(m(1), 4.0 / 0.5);
  EXPECT_DOUBLE_EQ(energy, (10.0 + 0.5 * 3.0 * 20.0 / 9.0) / 0.5);
}

// Cells [3, 5) on nodes [3, 6): node 5 and 4 empty leave cell 4 (the second) without mass.
TEST(GhostCells1D, The_first_empty_ghost_cell_is_returned_for_the_caller_to_name) {
  const std::vector<double> mass{2.0, 0.0, 0.0};
  const std::vector<Vec<1>> momentum(3, Vec<1>::Zero());
  const std::vector<double> internal{1.0, 0.0};
  const auto corners = corner_nodes(IndexBox<1>{{3}, {5}}, IndexBox<1>{{3}, {6}});
  std::vector<double> rho(2), energy(2);
  std::vector<Vec<1>> m(2);
  const std::vector<double> support{1.0, 1.0};
  const auto empty =
      fill_ghost_cells<1>({mass, momentum, internal}, corners, support, 1.0, {rho, m, energy});
  ASSERT_TRUE(empty.has_value());
  EXPECT_EQ(*empty, 1U);
  EXPECT_DOUBLE_EQ(rho[0], 1.0);  // (2 + 0) / 2: the cell with mass keeps its fill
}

TEST(GhostCells3D, Node_box_must_hold_every_corner) {
  EXPECT_THROW((void)corner_nodes(test::cube<3>(2, 4), test::cube<3>(2, 4)), Error);
}

}  // namespace
}  // namespace mpfd::coupler::handshake
