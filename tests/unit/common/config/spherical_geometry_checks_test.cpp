// domain.geometry: spherical (seed S, METHOD.md V10): one radial line from the
// centre, concentric spheres about the origin on grid lines with one particle
// count, run by mpm_solver. Each message names the key and what was expected.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "common/config/scene_loader.hpp"
#include "tests/unit/common/config/scene_test_support.hpp"

namespace mpfd::config::test {
namespace {

// Seed S's case at h = 20 mm: TNT a = 0.1 m in water to 2.5 m.
const std::string kUnderwater = R"(name: underwater
time: {end: 1.4e-3}
domain: {lower: [0, 0, 0], upper: [2.5, 0.02, 0.02], cells: [125, 1, 1], geometry: spherical}
materials:
  tnt:
    eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
  water: {eos: {type: polynomial, rho0: 1000, A1: 2.2e9, A2: 9.54e9, A3: 14.57e9, B0: 0.28, B1: 0.28, T1: 2.2e9}}
initial: {material: water, density: 1000, specific_internal_energy: 0}
output: {interval: 1.0e-4}
boundaries: {x_lower: symmetry, x_upper: non_reflecting}
)";
const std::string kUnderwaterCharge =
    "charges:\n  - {name: tnt, material: tnt, shape: {sphere: {center: [0, 0, 0], radius: 0.1}}, "
    "detonation_point: [0, 0, 0]}\n";
const std::string kMpm = "solver: {method: mpm, mpm: {shape_function: gimp}}\n";

std::string scene(const std::string& charges = kUnderwaterCharge,
                  const std::string& solver = kMpm) {
  return kUnderwater + charges + solver;
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  return text.replace(text.find(from), from.size(), to);
}

TEST(SphericalGeometryChecks, Seed_S_case_is_accepted) {
  const Scene s = parse_scene(scene(), "underwater.yaml");
  EXPECT_EQ(s.domain.geometry, Geometry::spherical);
  EXPECT_EQ(s.solver.mpm.update, MpmUpdate::musl);  // the default here: no usavg in 1D spherical
  const Scene plain = parse_scene(kMinimalScene, "tube.yaml");
  EXPECT_EQ(plain.domain.geometry, Geometry::cartesian);
}

TEST(SphericalGeometryChecks, Is_one_radial_line_from_the_centre_run_by_mpm) {
  // The charge then lies outside the domain too (two more errors).
  EXPECT_THAT(errors_of(replaced(scene(), "lower: [0, 0, 0]", "lower: [0.1, 0, 0]")),
              ::testing::Contains("scene.yaml:3:17: domain.lower: expected [0, 0, 0] with "
                                  "geometry spherical (x is the radius), got [0.1, 0, 0]"));
  expect_one(replaced(scene(), "[125, 1, 1]", "[125, 2, 1]"), "domain.cells",
             "expected [n, 1, 1] with geometry spherical (one radial line), got [125, 2, 1]");
  expect_one(replaced(scene(kUnderwaterCharge, "solver: {method: fdm}\n"),
                      "x_upper: non_reflecting", "x_upper: outflow"),
             "domain.geometry", "spherical is run by mpm_solver run; expected solver.method mpm");
  expect_one(scene(kUnderwaterCharge, "solver: {method: mpm, mpm: {shape_function: cpgimp}}\n"),
             "solver.mpm.shape_function", "expected linear or gimp with geometry spherical");
  expect_one(scene(kUnderwaterCharge, "solver: {method: mpm, mpm: {update: usavg}}\n"),
             "solver.mpm.update", "expected musl with geometry spherical");
}

TEST(SphericalGeometryChecks, Faces_are_the_centre_and_a_free_or_transmitting_surface) {
  expect_one(replaced(scene(), "x_lower: symmetry", "x_lower: wall"), "boundaries.x_lower",
             "expected symmetry with geometry spherical (x = 0 is the centre of the sphere)");
  expect_one(replaced(scene(), "x_upper: non_reflecting", "x_upper: wall"), "boundaries.x_upper",
             "expected outflow (a free surface) or non_reflecting (transmitting) with geometry "
             "spherical");
}

TEST(SphericalGeometryChecks, Regions_are_spheres_about_the_origin_on_grid_lines) {
  expect_one(scene("charges:\n  - {name: tnt, material: tnt, shape: {sphere: {center: [0.1, 0, "
                   "0], radius: 0.1}}, detonation_point: [0, 0, 0]}\n"),
             "charges[0].shape",
             "expected a sphere centred at [0, 0, 0] with geometry spherical (one shell of the "
             "radial line)");
  expect_one(scene("charges:\n  - {name: tnt, material: tnt, shape: {sphere: {center: [0, 0, 0], "
                   "radius: 0.11}}, detonation_point: [0, 0, 0]}\n"),
             "charges[0].shape",
             "expected a radius on a grid line (a multiple of the cell size 0.02 m), got 0.11 m");
  expect_one(scene("charges:\n  - {name: tnt, material: tnt, shape: {sphere: {center: [0, 0, 0], "
                   "radius: 0.1}}, detonation_point: [0.02, 0, 0]}\n"),
             "charges[0].detonation_point",
             "expected [0, 0, 0] with geometry spherical (the centre), got [0.02, 0, 0]");
  expect_one(scene("charges:\n  - {name: tnt, material: tnt, shape: {sphere: {center: [0, 0, 0], "
                   "radius: 0.1}}, burn: instantaneous}\n"),
             "charges[0].burn", "expected program with geometry spherical");
}

TEST(SphericalGeometryChecks, One_particle_count_of_at_least_two) {
  const std::string shell =
      "bodies:\n  - {name: shell, material: water, density: 1000, specific_internal_energy: 0, "
      "particles_per_axis: 3,\n     shape: {sphere: {center: [0, 0, 0], radius: 0.2}}}\n";
  expect_one(scene(shell + kUnderwaterCharge), "charges[0].particles_per_axis",
             "expected 3 as bodies[0] (one particle count per cell for the radial line), got 2");
  expect_one(scene(replaced(kUnderwaterCharge, "detonation_point",
                            "particles_per_axis: 1, detonation_point")),
             "charges[0].particles_per_axis",
             "expected >= 2 with geometry spherical (the Gauss points of each shell), got 1");
}

}  // namespace
}  // namespace mpfd::config::test
