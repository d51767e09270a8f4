// MpmSolver::restore refuses particles it could not map, before it changes
// anything: a particle off the grid (or at a non-finite position) would index
// blocks the sparse grid does not have. The state a refusal leaves advances as
// an untouched twin's, bit for bit.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

config::Scene scene() {
  return testing::gas_scene(
      "[1, 0.5, 0.015625]", "[32, 16, 1]",
      "bodies:\n" + testing::gas_body("hot", "[0, 0, 0]", "[0.3, 0.5, 0.015625]", 4.0, 10.0) +
          testing::gas_body("air", "[0.3, 0, 0]", "[1, 0.5, 0.015625]", 1.0, 1.0) +
          "boundaries: {x_lower: wall, x_upper: wall, y_lower: wall, y_upper: wall}\n"
          "solver: {method: mpm, mpm: {shape_function: gimp}}\n");
}

std::vector<double> positions(const MpmSolver& solver) {
  std::vector<double> out;
  for (const auto& axis : solver.particles().position)
    out.insert(out.end(), axis.begin(), axis.end());
  return out;
}

class MpmRestore : public ::testing::TestWithParam<double> {};

TEST_P(MpmRestore, AParticleOffTheGridIsNamedAndTheStateKept) {
  const config::Scene s = scene();
  MpmSolver solver(s, MpmSettings::from_scene(s));
  MpmSolver twin(s, MpmSettings::from_scene(s));
  for (MpmSolver* m : {&solver, &twin}) m->advance(m->stable_dt());
  ParticleSet moved = solver.particles();
  moved.position[1][7] = GetParam();
  EXPECT_THAT(
      [&] { solver.restore(moved, {}, 1.0, 40, solver.boundary_ledger(), 0.0); },
      ::testing::ThrowsMessage<Error>(
          AllOf(HasSubstr("restore: particle 7"), HasSubstr("on axis 1 is off the grid [0.000000, "
                                                            "0.500000)"))));
  EXPECT_EQ(solver.steps(), 1);
  for (MpmSolver* m : {&solver, &twin}) m->advance(m->stable_dt());
  EXPECT_EQ(positions(solver), positions(twin));
  EXPECT_EQ(solver.time(), twin.time());
}

INSTANTIATE_TEST_SUITE_P(Positions, MpmRestore,
                         ::testing::Values(-0.01, 0.5, 3.0e9,
                                           std::numeric_limits<double>::quiet_NaN()));

}  // namespace
}  // namespace mpfd::mpm
