// Gauges that follow the material (T §3.4.4 tracking points): binding to the
// nearest particle at t = 0 (lowest id on a tie, none within one cell is an
// error), identity through removal, and a moving body whose following gauge
// reads its own particle while a fixed gauge reads whichever passes.
#include "mpm_solver/followed_gauges.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/core/error.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

/// Particles at the given x (y = z = 0) with the given ids.
ParticleSet line(const std::vector<double>& x, const std::vector<std::uint64_t>& ids) {
  ParticleSet ps;
  ps.grow(x.size());
  for (std::size_t p = 0; p < x.size(); ++p) {
    ps.position[0][p] = x[p];
    ps.id[p] = ids[p];
  }
  return ps;
}

config::Gauge following(const std::string& name, double x) {
  return {name, {x, 0.0, 0.0}, config::GaugeFollow::material};
}

TEST(FollowedGauges, BindsTheNearestParticleAndTheLowestIdOnATie) {
  const ParticleSet ps = line({0.0, 1.0, 2.0, 3.0}, {40, 7, 30, 9});
  EXPECT_EQ(bind_to_particle(ps, following("g", 2.2), 1.0), 30U);
  // 1.5 is as near to x = 1 (id 7) as to x = 2 (id 30); 2.5 to ids 30 and 9.
  EXPECT_EQ(bind_to_particle(ps, following("g", 1.5), 1.0), 7U);
  EXPECT_EQ(bind_to_particle(ps, following("g", 2.5), 1.0), 9U);
}

TEST(FollowedGauges, RefusesAGaugeWithNoParticleWithinOneCell) {
  const ParticleSet ps = line({0.0, 1.0}, {1, 2});
  EXPECT_EQ(bind_to_particle(ps, following("g", 1.5), 0.5), 2U);  // exactly one cell: bound
  try {
    (void)bind_to_particle(ps, following("far", 2.75), 0.5);
    FAIL() << "bound a particle 1.75 m away with a 0.5 m cell";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "gauge 'far' at (2.75, 0, 0) m follows the material, but the nearest particle "
                 "is 1.75 m away; expected one within one cell (0.5 m)");
  }
  EXPECT_THROW((void)bind_to_particle(ParticleSet{}, following("g", 0.0), 0.5), Error);
}

TEST(FollowedGauges, KeepTheirParticleByIdThroughRemovalUntilItLeaves) {
  ParticleSet ps = line({0.0, 1.0, 2.0, 3.0}, {10, 11, 12, 13});
  const std::vector<config::Gauge> gauges = {
      following("a", 2.1),
      following("b", 3.0),
      {"fixed", {0.0, 0.0, 0.0}, config::GaugeFollow::point}};
  FollowedGauges followed(gauges, ps, 1.0);
  EXPECT_TRUE(followed.follows("a"));
  EXPECT_FALSE(followed.follows("fixed"));
  EXPECT_THROW((void)followed.particle("fixed", ps), Error);
  EXPECT_EQ(followed.particle("a", ps), 2U);
  EXPECT_EQ(followed.particle("b", ps), 3U);
  const std::vector<std::uint8_t> first = {1, 0, 0, 0};  // removes id 10: id 13 fills index 0
  ps.remove_flagged(first);
  EXPECT_EQ(followed.particle("a", ps), 2U);
  EXPECT_EQ(followed.particle("b", ps), 0U);
  EXPECT_EQ(ps.id[followed.particle("b", ps)], 13U);
  const std::vector<std::uint8_t> second = {0, 0, 1};  // removes id 12
  ps.remove_flagged(second);
  EXPECT_EQ(followed.particle("a", ps), FollowedGauges::kLeft);
  EXPECT_EQ(ps.id[followed.particle("b", ps)], 13U);
}

TEST(FollowedGauges, AFollowingGaugeRidesItsParticleWhereAFixedOneDoesNot) {
  // A 0.4 m gas slab at 1 Pa moving at 50 m/s through a 1 m domain of 10 cells:
  // its rarefactions travel 1.2 mm in 1 ms, so its inner particles move rigidly.
  const auto scene = testing::gas_scene(
      "[1, 0.5, 0.1]", "[10, 5, 1]",
      "bodies:\n" +
          testing::gas_body("slab", "[0.2, 0, 0]", "[0.6, 0.5, 0.1]", 1.0, 1.0, "[50, 0, 0]") +
          "boundaries: {x_lower: outflow, x_upper: outflow}\nsolver: {method: mpm}\n");
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  // Nearest at t = 0: the particle at x = 0.425 (x0), y = 0.275, z = 0.025 (lowest id of two).
  const std::vector<config::Gauge> gauges = {
      {"g", {0.41, 0.27, 0.05}, config::GaugeFollow::material}};
  FollowedGauges followed(gauges, solver.particles(), binding_reach(solver.grid()));
  EXPECT_EQ(binding_reach(solver.grid()), 0.1);
  const std::size_t p0 = followed.particle("g", solver.particles());
  const double x0 = solver.particles().position[0][p0];
  const std::uint64_t id = solver.particles().id[p0];
  EXPECT_EQ(followed.id("g"), id);
  while (solver.time() < 1.0e-3) solver.advance(solver.step_toward(1.0e-3));
  const ParticleSet& ps = solver.particles();
  const std::size_t p = followed.particle("g", ps);
  ASSERT_NE(p, FollowedGauges::kLeft);
  EXPECT_EQ(ps.id[p], id);
  // 50 m/s x 1 ms = 50 mm = half a cell. The 1 Pa free surfaces pull the
  // half-filled nodes by ~ p / (rho h) = 10 m/s^2: 0.01 m/s and 10 um at most.
  EXPECT_NEAR(ps.position[0][p] - x0, 0.05, 1e-5);
  EXPECT_NEAR(ps.velocity[0][p], 50.0, 0.01);
  // The fixed point now reads the particle that was 50 mm upstream (x0 - 0.05 at t = 0).
  const std::size_t fixed = nearest_particle(ps, gauges[0].position);
  EXPECT_NE(ps.id[fixed], id);
  EXPECT_NEAR(ps.position[0][fixed] - ps.position[0][p], -0.05, 1e-5);
}

}  // namespace
}  // namespace mpfd::mpm
