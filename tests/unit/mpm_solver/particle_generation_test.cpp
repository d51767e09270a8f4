#include "mpm_solver/particle_generation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/core/error.hpp"
#include "common/initial/initial_cells.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

TEST(ParticleGeneration, FillsBodiesWithNPerAxisAndExactMass) {
  // 2D, 10 x 4 cells of 0.1 m; a body over the left half, 3 particles per axis.
  const auto scene =
      testing::gas_scene("[1, 0.4, 0.1]", "[10, 4, 1]",
                         "bodies:\n" + testing::gas_body("left", "[0, 0, 0]", "[0.5, 0.4, 0.1]",
                                                         2.0, 1.0, "[3, 0, 0]", 3));
  const auto generated = generate_particles(scene, initial::scene_grid(scene));
  const auto& ps = generated.particles;
  ASSERT_EQ(ps.size(), 5u * 4u * 9u);
  double mass = 0.0;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    mass += ps.mass[p];
    EXPECT_LT(ps.position[0][p], 0.5);
    EXPECT_DOUBLE_EQ(ps.position[2][p], 0.05);  // the single layer of the inactive axis
    EXPECT_DOUBLE_EQ(ps.velocity[0][p], 3.0);
    // ideal gas: e = p / ((gamma - 1) rho)
    EXPECT_DOUBLE_EQ(ps.specific_internal_energy[p], 1.0 / (0.4 * 2.0));
  }
  EXPECT_NEAR(mass, 2.0 * 0.5 * 0.4 * 0.1, 1e-15);
  ASSERT_EQ(generated.bodies.size(), 1u);
  EXPECT_DOUBLE_EQ(generated.bodies[0].half_width[0], 1.0 / 6.0);
  EXPECT_DOUBLE_EQ(generated.bodies[0].half_width[2], 0.5);
  EXPECT_NEAR(generated.bodies[0].characteristic_length, 0.1 / 3.0, 1e-15);
}

TEST(ParticleGeneration, LaterBodiesOwnTheirRegionAndTheBackgroundIsEmpty) {
  const auto scene = testing::gas_scene(
      "[1, 0.1, 0.1]", "[10, 1, 1]",
      "bodies:\n" + testing::gas_body("a", "[0, 0, 0]", "[0.6, 0.1, 0.1]", 1.0, 1.0) +
          testing::gas_body("b", "[0.4, 0, 0]", "[0.8, 0.1, 0.1]", 1.0, 1.0));
  const auto ps = generate_particles(scene, initial::scene_grid(scene)).particles;
  ASSERT_EQ(ps.size(), 16u);  // a: 0..0.4 (8), b: 0.4..0.8 (8); nothing beyond 0.8
  for (std::size_t p = 0; p < ps.size(); ++p)
    EXPECT_EQ(ps.body[p], ps.position[0][p] < 0.4 ? 0 : 1);
}

TEST(ParticleGeneration, ProgramBurnLightingTimeIsDistanceOverD) {
  const std::string text = R"(
name: slab
time: {end: 1.0e-6}
domain: {lower: [0, 0, 0], upper: [0.01, 1.0e-4, 1.0e-4], cells: [100, 1, 1]}
materials:
  tnt:
    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
initial: {material: tnt, density: 1630, specific_internal_energy: 0}
charges:
  - {name: c, material: tnt, shape: {box: {lower: [0, 0, 0], upper: [0.01, 1.0e-4, 1.0e-4]}},
     detonation_point: [0, 5.0e-5, 5.0e-5], burn: program}
output: {interval: 1.0e-6}
solver: {method: mpm}
)";
  const auto scene = config::parse_scene(text, "slab.yaml");
  const auto generated = generate_particles(scene, initial::scene_grid(scene));
  const auto& ps = generated.particles;
  ASSERT_EQ(ps.size(), 200u);
  for (std::size_t p = 0; p < ps.size(); ++p) {
    EXPECT_NEAR(ps.lighting_time[p], ps.position[0][p] / 6930.0, 1e-18);
    EXPECT_DOUBLE_EQ(ps.density[p], 1630.0);
    EXPECT_DOUBLE_EQ(ps.specific_internal_energy[p], 6.993e9 / 1630.0);
  }
  // h = particle spacing 0.05 mm; rate = D / (1.5 h).
  EXPECT_NEAR(generated.bodies[0].burn_rate, 6930.0 / (1.5 * 5.0e-5), 1e-3);
}

TEST(ParticleGeneration, ABodyOutsideTheDomainIsAnError) {
  const auto scene = testing::gas_scene(
      "[1, 0.1, 0.1]", "[10, 1, 1]",
      "bodies:\n" + testing::gas_body("a", "[0, 0, 0]", "[0.6, 0.1, 0.1]", 1.0, 1.0) +
          testing::gas_body("b", "[0, 0, 0]", "[0.6, 0.1, 0.1]", 1.0, 1.0));
  EXPECT_THROW(
      {
        try {
          (void)generate_particles(scene, initial::scene_grid(scene));
        } catch (const Error& e) {
          EXPECT_NE(std::string(e.what()).find("body 'a'"), std::string::npos);
          throw;
        }
      },
      Error);
}

}  // namespace
}  // namespace mpfd::mpm
