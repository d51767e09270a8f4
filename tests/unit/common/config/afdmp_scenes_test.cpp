// The AFDMP and V10 scenes of configs/ (design §4) load and hold the thesis's
// and seed S's numbers; the coupler and mpm_solver run them.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <variant>

#include "common/config/scene_loader.hpp"
#include "tests/unit/common/config/scene_test_support.hpp"

namespace mpfd::config::test {
namespace {

double h(const Scene& s, int axis) {
  return (s.domain.upper[axis] - s.domain.lower[axis]) / s.domain.cells[axis];
}

double charge_mass(const Scene& s) {
  const Charge& c = s.charges.at(0);
  const double rho0 = std::get<eos::Jwl>(find_material(s, c.material)->eos).rho0;
  if (const auto* ball = std::get_if<Sphere>(&c.shape.kind))
    return 4.0 / 3.0 * std::numbers::pi * std::pow(ball->radius, 3) * rho0;
  const auto& box = std::get<Box>(c.shape.kind);
  double volume = 1.0;
  for (int i = 0; i < 3; ++i) volume *= box.upper[i] - box.lower[i];
  return volume * rho0;
}

TEST(AfdmpScenes, V3_is_the_thesis_quarter_at_1mm) {
  const Scene s = load_scene(kConfigs / "afdmp_blast_2d.yaml");
  EXPECT_EQ(s.solver.method, Method::afdmp);
  EXPECT_EQ(s.solver.afdmp.start, AfdmpStart::mpm);
  EXPECT_FALSE(s.zones.has_value());
  EXPECT_NEAR(h(s, 0), 1e-3, 1e-15);
  EXPECT_EQ(s.domain.cells, (std::array<int, 3>{500, 500, 1}));
  EXPECT_EQ(std::get<Cylinder>(s.charges.at(0).shape.kind).radius, 0.05);
  EXPECT_EQ(s.charges[0].particles_per_axis, 2);
  EXPECT_EQ(s.bodies.at(0).particles_per_axis, 1);
  EXPECT_EQ(s.time.end, 9.0e-5);
  EXPECT_EQ(s.gauges.size(), 6u);
}

TEST(AfdmpScenes, V4_cube_octant_holds_13_grams_of_tnt) {
  const Scene s = load_scene(kConfigs / "afdmp_free_air_3d.yaml");
  EXPECT_EQ(s.domain.cells, (std::array<int, 3>{100, 100, 100}));
  EXPECT_NEAR(h(s, 0), 2.5e-3, 1e-15);
  EXPECT_NEAR(8.0 * charge_mass(s), 13.04e-3, 1e-5);  // the full 20 mm cube
  EXPECT_EQ(s.charges[0].detonation_point, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.gauges.size(), 18u);
  for (const Gauge& g : s.gauges) {
    const double r = std::hypot(g.position[0], g.position[1], g.position[2]);
    EXPECT_GE(r, 0.06 - 1e-6) << g.name;
    EXPECT_LE(r, 0.38 + 1e-6) << g.name;
  }
}

TEST(AfdmpScenes, V4_sphere_has_the_cube_mass_and_starts_in_1d) {
  const Scene s = load_scene(kConfigs / "afdmp_free_air_3d_1d.yaml");
  EXPECT_EQ(s.solver.afdmp.start, AfdmpStart::spherical);
  EXPECT_EQ(s.solver.afdmp.spherical.handoff_radius, 0.04);
  EXPECT_NEAR(charge_mass(s), 13.04e-3, 2e-5);  // the whole sphere: the 1D line is spherical
  const double radius = std::get<Sphere>(s.charges[0].shape.kind).radius;
  const double cells = radius / *s.solver.afdmp.spherical.grid_spacing;
  EXPECT_NEAR(cells, std::round(cells), 1e-9);
  const Scene cube = load_scene(kConfigs / "afdmp_free_air_3d.yaml");
  EXPECT_EQ(s.domain.cells, cube.domain.cells);
  EXPECT_EQ(s.gauges.size(), cube.gauges.size());
}

TEST(AfdmpScenes, V5_plate_lies_in_the_fsi_zone_with_thesis_steel) {
  const Scene s = load_scene(kConfigs / "afdmp_steel_plate_2d.yaml");
  ASSERT_TRUE(s.zones && s.zones->mpm);
  EXPECT_EQ(s.zones->mpm->lower[0], 0.30);
  EXPECT_EQ(s.zones->mpm->activation_pressure, 2.0e5);
  const Material* steel = find_material(s, s.bodies.at(1).state.material);
  ASSERT_NE(steel, nullptr);
  const auto& jc = std::get<JohnsonCook>(steel->strength);
  EXPECT_EQ(jc.a, 350e6);
  EXPECT_EQ(jc.b, 275e6);
  EXPECT_EQ(jc.n, 0.36);
  EXPECT_EQ(jc.c, 0.022);
  EXPECT_EQ(std::get<eos::MieGruneisen>(steel->eos).rho0, 7890);
  EXPECT_EQ(s.bodies[1].particles_per_axis, 2);
  EXPECT_EQ(s.solver.mpm.reference_pressure, 101356.5);
  EXPECT_EQ(s.gauges.size(), 2u);
}

TEST(AfdmpScenes, V10_is_seed_S_case) {
  const Scene s = load_scene(kConfigs / "underwater_1d.yaml");
  EXPECT_EQ(s.domain.geometry, Geometry::spherical);
  EXPECT_NEAR(h(s, 0), 0.01, 1e-15);
  EXPECT_EQ(s.domain.upper[0], 5.0);
  EXPECT_EQ(std::get<Sphere>(s.charges.at(0).shape.kind).radius, 0.1);
  EXPECT_TRUE(std::holds_alternative<eos::Polynomial>(find_material(s, "water")->eos));
  EXPECT_EQ(s.gauges.size(), 9u);
}

}  // namespace
}  // namespace mpfd::config::test
