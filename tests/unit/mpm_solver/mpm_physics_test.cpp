// The step's optional physics: multi-velocity-field contact, fixed particle
// sets, gravity and shear-mode damping (momentum bookkeeping and the cost-free
// paths); the accuracy checks are in tests/verification/mpm.

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

using config::ShapeFunction;

MpmSettings physics_settings(ShapeFunction shape, double shear_damping = 0.0) {
  MpmSettings s;
  s.shape_function = shape;
  s.shear_damping = shear_damping;
  return s;
}

// Two gas slabs flying into each other in 2D, and their MPM solver options.
config::Scene collision(const std::string& mpm_options, const std::string& boundaries = "") {
  return testing::gas_scene(
      "[1, 0.2, 0.1]", "[50, 10, 1]",
      "bodies:\n" +
          testing::gas_body("left", "[0.2, 0, 0]", "[0.45, 0.2, 0.1]", 1.0, 1.0e5, "[300, 40, 0]") +
          testing::gas_body("right", "[0.5, 0, 0]", "[0.7, 0.2, 0.1]", 4.0, 2.0e5, "[-100, 0, 0]") +
          boundaries + "solver: {method: mpm, mpm: " + mpm_options + "}\n");
}

class Shapes : public ::testing::TestWithParam<ShapeFunction> {};

// Contact forces are equal and opposite at every node, T (2-29) with the
// misprint corrected: the collision keeps its momentum to round-off (what the
// gas carries out through the open faces is in the ledger).
TEST_P(Shapes, ContactConservesMomentumInACollision) {
  const auto scene = collision("{contact: {friction: 0.3}}");
  MpmSolver solver(scene, physics_settings(GetParam()));
  const MpmTotals before = solver.totals();
  solver.advance_to(3.0e-4);
  const MpmTotals after = solver.totals();
  const auto& ledger = solver.boundary_ledger();
  const double scale = 1.0;  // kg m/s: |p| of each body is 1 to 2
  EXPECT_NEAR(after.momentum[0] + ledger.momentum[0], before.momentum[0], 1e-12 * scale);
  EXPECT_NEAR(after.momentum[1] + ledger.momentum[1], before.momentum[1], 1e-12 * scale);
}

// With walls the wall impulse lands in the ledger with contact on as well.
TEST_P(Shapes, WallImpulseWithContactIsInTheLedger) {
  const auto scene =
      collision("{contact: {}}", "boundaries: {x_lower: wall, x_upper: wall, y_lower: symmetry}\n");
  MpmSolver solver(scene, physics_settings(GetParam()));
  const MpmTotals before = solver.totals();
  solver.advance_to(2.0e-3);
  const MpmTotals after = solver.totals();
  EXPECT_GT(std::abs(after.momentum[0] - before.momentum[0]), 0.1 * std::abs(before.momentum[0]));
  EXPECT_NEAR(after.momentum[0] + solver.boundary_ledger().momentum[0], before.momentum[0], 1e-12);
}

// Shear-mode damping forces sum to zero over each cell: momentum is kept.
TEST_P(Shapes, ShearDampingKeepsMomentum) {
  const auto scene = collision("{}");
  MpmSolver solver(scene, physics_settings(GetParam(), 0.5));
  const MpmTotals before = solver.totals();
  solver.advance_to(3.0e-4);
  const MpmTotals after = solver.totals();
  const auto& ledger = solver.boundary_ledger();
  EXPECT_NEAR(after.momentum[0] + ledger.momentum[0], before.momentum[0], 1e-12);
  EXPECT_NEAR(after.momentum[1] + ledger.momentum[1], before.momentum[1], 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Mpm, Shapes,
                         ::testing::Values(ShapeFunction::linear, ShapeFunction::gimp,
                                           ShapeFunction::cpgimp));

// Bodies that never share a node see only the single-field step: contact on
// gives the same bits as contact off.
TEST(MpmPhysics, ContactWithoutSharedNodesIsTheSingleFieldStep) {
  const auto run = [](const std::string& options) {
    const auto scene = testing::gas_scene(
        "[1, 0.2, 0.1]", "[50, 10, 1]",
        "bodies:\n" +
            testing::gas_body("a", "[0.1, 0, 0]", "[0.3, 0.2, 0.1]", 1.0, 1.0e5, "[20, 5, 0]") +
            testing::gas_body("b", "[0.6, 0, 0]", "[0.8, 0.2, 0.1]", 2.0, 1.0e5, "[-10, 0, 0]") +
            "solver: {method: mpm, mpm: " + options + "}\n");
    MpmSolver solver(scene, physics_settings(ShapeFunction::gimp));
    solver.advance_to(1.0e-4);
    return solver.particles().position[0];
  };
  const auto with = run("{contact: {}}");
  const auto without = run("{}");
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t p = 0; p < with.size(); ++p) ASSERT_EQ(with[p], without[p]) << p;
}

// Contact's per-body fields are gathered in the same coloured scatters: the
// result does not depend on the number of threads.
TEST(MpmPhysics, ContactIsBitwiseIndependentOfThreadCount) {
  const auto scene = testing::gas_scene(
      "[1, 1, 0.1]", "[128, 128, 1]",
      "bodies:\n" + testing::gas_body("air", "[0, 0, 0]", "[1, 1, 0.1]", 1.2, 1.0e5) +
          testing::gas_body("hot", "[0.4, 0.4, 0]", "[0.6, 0.6, 0.1]", 10.0, 1.0e7) +
          "solver: {method: mpm, mpm: {contact: {friction: 0.1}}}\n");
  const auto run = [&](int threads) {
    omp_set_num_threads(threads);
    MpmSolver solver(scene, physics_settings(ShapeFunction::gimp, 0.1));
    for (int i = 0; i < 5; ++i) solver.advance(solver.stable_dt());
    return solver.particles().position[0];
  };
  const auto one = run(1);
  const auto two = run(2);
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t p = 0; p < one.size(); ++p) ASSERT_EQ(one[p], two[p]) << p;
}

// A fixed particle set holds the nodes it touches (no contact): gas pushed
// against it stops there, its particles do not move, and its impulse is booked.
TEST(MpmPhysics, FixedParticleSetHoldsItsNodesAndBooksItsImpulse) {
  for (const auto shape : {ShapeFunction::linear, ShapeFunction::gimp}) {
    auto scene = testing::gas_scene(
        "[1, 0.1, 0.1]", "[50, 1, 1]",
        "bodies:\n" +
            testing::gas_body("gas", "[0.2, 0, 0]", "[0.6, 0.1, 0.1]", 1.0, 1.0e5, "[100, 0, 0]") +
            testing::gas_body("clamp", "[0.6, 0, 0]", "[0.7, 0.1, 0.1]", 1.0, 1.0e5) +
            "solver: {method: mpm}\n");
    scene.bodies[1].fixed = true;
    MpmSolver solver(scene, physics_settings(shape));
    // Removal may reorder the particles: compare the clamp's positions sorted.
    const auto clamp_positions = [&] {
      std::vector<double> x;
      for (std::size_t p = 0; p < solver.particles().size(); ++p)
        if (solver.particles().body[p] == 1) x.push_back(solver.particles().position[0][p]);
      std::sort(x.begin(), x.end());
      return x;
    };
    const auto clamp_x = clamp_positions();
    const MpmTotals before = solver.totals();
    solver.advance_to(2.0e-3);
    const MpmTotals after = solver.totals();
    const auto& ps = solver.particles();
    EXPECT_EQ(clamp_positions(), clamp_x);
    double rightmost_gas = 0.0;
    for (std::size_t p = 0; p < ps.size(); ++p) {
      if (ps.body[p] == 1)
        ASSERT_EQ(ps.velocity[0][p], 0.0);
      else
        rightmost_gas = std::max(rightmost_gas, ps.position[0][p]);
    }
    EXPECT_LT(rightmost_gas, 0.6);  // held at the clamp's first node
    EXPECT_GT(std::abs(after.momentum[0] - before.momentum[0]), 0.5 * before.momentum[0]);
    EXPECT_NEAR(after.momentum[0] + solver.boundary_ledger().momentum[0], before.momentum[0],
                1e-12 * before.momentum[0]);
  }
}

// Gravity: a free body in free fall, no face touched.
TEST(MpmPhysics, GravityAcceleratesAFreeBody) {
  const auto scene = testing::gas_scene(
      "[1, 1, 0.1]", "[10, 10, 1]",
      "bodies:\n" + testing::gas_body("ball", "[0.4, 0.4, 0]", "[0.6, 0.6, 0.1]", 1.0, 1.0) +
          "solver: {method: mpm, mpm: {gravity: [0, -9.81, 0]}}\n");
  MpmSolver solver(scene, physics_settings(ShapeFunction::linear));
  solver.advance_to(0.01);
  const MpmTotals t = solver.totals();
  EXPECT_NEAR(t.momentum[1] / t.mass, -9.81 * 0.01, 1e-12);
}

}  // namespace
}  // namespace mpfd::mpm
