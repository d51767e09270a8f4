// MpmSolver::map_particles_to_node_box, the coupler's ghost_nodes export: it
// maps only the particles that reach the box, yet must give the full
// particle-to-grid scatter's node mass and momentum (T (2-12), (2-9)) bit for
// bit, for trilinear and GIMP stencils, 2D and 3D, after the particles have
// moved off their lattice (so that the summation order matters).
#include <gtest/gtest.h>

#include <string>

#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

using testing::gas_body;
using testing::gas_scene;

/// Expects the box map to equal map_particles_to_nodes + node_state everywhere in [lo, hi).
void expect_box_matches_full_map(MpmSolver& solver, const grid::Index3& lo,
                                 const grid::Index3& hi) {
  NodeBoxMap box;
  solver.map_particles_to_node_box(lo, hi, box);
  solver.map_particles_to_nodes();
  std::size_t n = 0;
  double total = 0.0;
  for (int i = lo[0]; i < hi[0]; ++i)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int k = lo[2]; k < hi[2]; ++k, ++n) {
        const NodeState full = solver.node_state({i, j, k});
        ASSERT_EQ(box.mass[n], full.mass) << "node " << i << " " << j << " " << k;
        for (std::size_t a = 0; a < 3; ++a)
          ASSERT_EQ(box.momentum[3 * n + a], full.momentum[a])
              << "node " << i << " " << j << " " << k << " axis " << a;
        total += box.mass[n];
      }
  ASSERT_EQ(n, box.mass.size());
  EXPECT_GT(total, 0.0);
  for (std::size_t i = 1; i < box.reaching.size(); ++i)
    EXPECT_LT(box.reaching[i - 1], box.reaching[i]);  // index order
}

class NodeBoxMapTest : public ::testing::TestWithParam<std::string> {};

TEST_P(NodeBoxMapTest, EqualsTheFullScatterBitForBit2D) {
  // A blast in 32 x 16 cells: after 15 steps the particles sit off their lattice.
  const auto scene = gas_scene(
      "[1, 0.5, 0.015625]", "[32, 16, 1]",
      "bodies:\n" + gas_body("hot", "[0, 0, 0]", "[0.3, 0.5, 0.015625]", 4.0, 10.0) +
          gas_body("air", "[0.3, 0, 0]", "[1, 0.5, 0.015625]", 1.0, 1.0, "[0.3, 0.2, 0]") +
          "boundaries: {x_lower: wall, x_upper: wall, y_lower: wall, y_upper: wall}\n"
          "solver: {method: mpm, mpm: {shape_function: " +
          GetParam() + ", update: musl}}\n");
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  for (int step = 0; step < 15; ++step) solver.advance(solver.stable_dt());
  expect_box_matches_full_map(solver, {9, 0, 0}, {13, 17, 1});  // a ghost-node box of w = 4
  expect_box_matches_full_map(solver, {0, 0, 0}, {33, 17, 1});  // every node
  expect_box_matches_full_map(solver, {7, 3, 0}, {8, 11, 1});   // one column, block edges
}

TEST_P(NodeBoxMapTest, EqualsTheFullScatterBitForBit3D) {
  const auto scene = gas_scene(
      "[1, 0.5, 0.5]", "[16, 8, 8]",
      "bodies:\n" + gas_body("hot", "[0, 0, 0]", "[0.3, 0.5, 0.5]", 4.0, 10.0) +
          gas_body("air", "[0.3, 0, 0]", "[1, 0.5, 0.5]", 1.0, 1.0, "[0.3, 0.2, 0.1]") +
          "solver: {method: mpm, mpm: {shape_function: " + GetParam() + ", update: musl}}\n");
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  for (int step = 0; step < 6; ++step) solver.advance(solver.stable_dt());
  expect_box_matches_full_map(solver, {4, 0, 0}, {8, 9, 9});
  expect_box_matches_full_map(solver, {3, 2, 5}, {6, 7, 9});
}

INSTANTIATE_TEST_SUITE_P(Stencils, NodeBoxMapTest, ::testing::Values("linear", "gimp", "cpgimp"));

}  // namespace
}  // namespace mpfd::mpm
