// Scene checks of solver.method afdmp (design §4): a charge, the FSI zone (its
// activation pressure, one inner face, the structures inside it, no contact),
// and start: spherical (3D, one centre-initiated sphere, the ball of
// 1.25 x handoff_radius clear of the FSI zone and of non-mirror faces). Each
// message names the file, the key and what was expected.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "common/config/scene_loader.hpp"
#include "tests/unit/common/config/scene_test_support.hpp"

namespace mpfd::config::test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// The V5 shape (T §3.4.4) at h = 10 mm: TNT at the origin, a steel plate in
// the FSI zone x in [0.3, 0.5].
const std::string kMaterials = R"(materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
  tnt:
    eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
  steel:
    eos: {type: mie_gruneisen, rho0: 7890, C0: 4569, S: 1.49, gamma0: 2.17}
    strength: {type: johnson_cook, A: 350e6, B: 275e6, n: 0.36, C: 0.022, m: 1.0,
               T_melt: 1811, specific_heat: 452, shear_modulus: 81.8e9}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
output: {interval: 1.0e-5}
)";

const std::string kCharge =
    "charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0, 0, 0], radius: 0.05}}, "
    "detonation_point: [0, 0, 0]}\n";
const std::string kPlate =
    "bodies:\n  - {name: plate, material: steel, density: 7890, specific_internal_energy: 0,\n"
    "     shape: {box: {lower: [0.35, 0, 0], upper: [0.37, 0.25, 0.01]}}}\n";
const std::string kZone =
    "zones:\n  mpm: {lower: [0.3, 0, 0], upper: [0.5, 0.5, 0.01], activation_pressure: 2.0e5}\n";

std::string plate_scene(const std::string& zone = kZone, const std::string& charge = kCharge,
                        const std::string& plate = kPlate, const std::string& solver = "") {
  return "name: v5\ntime: {end: 3.0e-4}\n"
         "domain: {lower: [-0.5, 0, 0], upper: [0.5, 0.5, 0.01], cells: [100, 50, 1]}\n" +
         kMaterials + charge + plate + zone + "solver: {method: afdmp" + solver + "}\n";
}

TEST(AfdmpChecks, The_V5_shape_is_accepted_with_its_plate_zone_and_charge) {
  const Scene s = parse_scene(plate_scene(), "v5.yaml");
  EXPECT_EQ(s.solver.afdmp.start, AfdmpStart::mpm);
  EXPECT_EQ(s.domain.geometry, Geometry::cartesian);
}

TEST(AfdmpChecks, Needs_a_charge) {
  expect_one(plate_scene(kZone, ""), "solver.method",
             "afdmp needs at least one charge (phase 1 is its detonation, T §3.2.1); got none");
}

TEST(AfdmpChecks, Fsi_zone_needs_an_activation_pressure) {
  expect_one(plate_scene("zones:\n  mpm: {lower: [0.3, 0, 0], upper: [0.5, 0.5, 0.01]}\n"),
             "zones.mpm", "activation_pressure is required with solver.method afdmp");
}

TEST(AfdmpChecks, Fsi_zone_has_exactly_one_inner_face) {
  expect_one(plate_scene("zones:\n  mpm: {lower: [0.3, 0, 0], upper: [0.5, 0.4, 0.01], "
                         "activation_pressure: 2.0e5}\n"),
             "zones.mpm",
             "expected an FSI zone with exactly one face inside the domain (a slab across it, "
             "the other faces on the domain's boundary), got 2: x = 0.3, y = 0.4");
}

TEST(AfdmpChecks, Charges_detonate_in_the_fluid_zone) {
  expect_one(plate_scene(kZone,
                         "charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0.4, "
                         "0.4, 0], radius: 0.05}}, detonation_point: [0.4, 0.4, 0]}\n"),
             "charges[0].shape",
             "expected a charge outside zones.mpm [0.3, 0, 0] to [0.5, 0.5, 0.01] (it detonates "
             "in the fluid zone, T §3.2.1)");
}

TEST(AfdmpChecks, Structures_lie_inside_the_fsi_zone) {
  const std::string outside =
      "bodies:\n  - {name: plate, material: steel, density: 7890, specific_internal_energy: 0,\n"
      "     shape: {box: {lower: [0.25, 0, 0], upper: [0.37, 0.25, 0.01]}}}\n";
  expect_one(plate_scene(kZone, kCharge, outside), "bodies[0].shape",
             "expected a body with a strength model inside zones.mpm [0.3, 0, 0] to [0.5, 0.5, "
             "0.01] (structures live in the FSI zone, T §3.2.3)");
  expect_one(plate_scene("", kCharge, kPlate), "bodies[0]",
             "a body with a strength model needs zones.mpm around it");
}

TEST(AfdmpChecks, Contact_is_refused_with_an_fsi_zone) {
  expect_one(plate_scene(kZone, kCharge, kPlate, ", mpm: {contact: {friction: 0.1}}"),
             "solver.mpm.contact",
             "not with an FSI zone under afdmp: the MPM refuses coupler particles with contact");
}

TEST(AfdmpChecks, Reference_pressure_is_allowed) {
  const Scene s = parse_scene(
      plate_scene(kZone, kCharge, kPlate, ", mpm: {reference_pressure: 101325}"), "v5.yaml");
  EXPECT_EQ(s.solver.mpm.reference_pressure, 101325.0);
}

// V4's octant (T §3.4.3) at h = 10 mm with a sphere of r = 12.5 mm at the origin.
std::string octant(const std::string& charges, const std::string& spherical,
                   const std::string& extra = "", const std::string& cells = "[25, 25, 25]") {
  return "name: v4\ntime: {end: 3.0e-4}\n"
         "domain: {lower: [0, 0, 0], upper: [0.25, 0.25, 0.25], cells: " +
         cells + "}\n" + kMaterials + charges +
         "boundaries: {x_lower: symmetry, y_lower: symmetry, z_lower: symmetry}\n" + extra +
         "solver:\n  method: afdmp\n  afdmp:\n    start: spherical\n    spherical: " + spherical +
         "\n";
}

const std::string kSphere =
    "charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0, 0, 0], radius: "
    "0.0125}}, detonation_point: [0, 0, 0]}\n";
const std::string kHandoff = "{handoff_radius: 0.04}";

TEST(AfdmpChecks, Spherical_start_keys_arrive_with_their_defaults) {
  const Scene s = parse_scene(octant(kSphere, kHandoff), "v4.yaml");
  const AfdmpSpherical& o = s.solver.afdmp.spherical;
  EXPECT_EQ(s.solver.afdmp.start, AfdmpStart::spherical);
  EXPECT_EQ(o.handoff_radius, 0.04);
  EXPECT_EQ(o.front_overpressure, 1000.0);
  EXPECT_FALSE(o.grid_spacing.has_value());
  EXPECT_EQ(o.particles_per_cell, 2);
  EXPECT_EQ(o.shape_function, ShapeFunction::gimp);
  EXPECT_EQ(o.cfl, 0.2);
  const Scene t =
      parse_scene(octant(kSphere,
                         "{handoff_radius: 0.04, front_overpressure: 500, grid_spacing: 6.25e-4, "
                         "particles_per_cell: 3, shape_function: linear, cfl: 0.1}"),
                  "v4.yaml");
  EXPECT_EQ(t.solver.afdmp.spherical.grid_spacing, 6.25e-4);
  EXPECT_EQ(t.solver.afdmp.spherical.shape_function, ShapeFunction::linear);
  EXPECT_EQ(t.solver.afdmp.spherical.cfl, 0.1);
  EXPECT_THAT(errors_of(octant(kSphere, "{handoff_radius: 0.04, shape_function: cpgimp}")),
              ElementsAre(HasSubstr("solver.afdmp.spherical.shape_function: expected one of: "
                                    "linear, gimp")));
  EXPECT_THAT(errors_of(octant(kSphere, "{handoff_radius: 0.04, particles_per_cell: 1}")),
              ElementsAre(HasSubstr("solver.afdmp.spherical.particles_per_cell")));
}

TEST(AfdmpChecks, Spherical_start_needs_3d_and_a_handoff_radius) {
  expect_one(octant(kSphere, kHandoff, "", "[25, 25, 1]"), "solver.afdmp.start",
             "spherical needs a 3D grid (domain.cells > 1 on every axis), got [25, 25, 1]");
  expect_one(octant(kSphere, "{cfl: 0.2}"), "solver.afdmp.spherical",
             "handoff_radius is required with start: spherical");
  expect_one(octant(kSphere, "{handoff_radius: 0.01}"), "solver.afdmp.spherical.handoff_radius",
             "expected more than the charge radius 0.0125 m, got 0.01");
}

TEST(AfdmpChecks, Spherical_start_takes_one_centre_initiated_sphere) {
  expect_one(octant(kSphere + "  - {name: d, material: tnt, shape: {sphere: {center: [0.1, 0.1, "
                              "0.1], radius: 0.01}}, detonation_point: [0.1, 0.1, 0.1]}\n",
                    kHandoff),
             "solver.afdmp.start", "spherical expects exactly one charge, got 2");
  expect_one(octant("charges:\n  - {name: c, material: tnt, shape: {box: {lower: [0, 0, 0], "
                    "upper: [0.01, 0.01, 0.01]}}, detonation_point: [0, 0, 0]}\n",
                    kHandoff),
             "charges[0].shape", "expected a sphere with solver.afdmp.start: spherical");
  expect_one(octant("charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0, 0, 0], "
                    "radius: 0.0125}}, detonation_point: [0.01, 0, 0]}\n",
                    kHandoff),
             "charges[0].detonation_point",
             "expected the sphere's centre [0, 0, 0] with solver.afdmp.start: spherical, got "
             "[0.01, 0, 0]");
  expect_one(octant("charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0, 0, 0], "
                    "radius: 0.0125}}, burn: instantaneous}\n",
                    kHandoff),
             "charges[0].burn", "expected program with solver.afdmp.start: spherical");
}

TEST(AfdmpChecks, Spherical_start_charge_radius_is_on_the_1d_grid) {
  expect_one(octant("charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0, 0, 0], "
                    "radius: 0.01241}}, detonation_point: [0, 0, 0]}\n",
                    kHandoff),
             "solver.afdmp.spherical",
             "expected the charge radius 0.01241 m to be a multiple of the 1D grid spacing, got "
             "spacing 0.0025 m; set grid_spacing to e.g. 0.002482 m");
}

TEST(AfdmpChecks, Spherical_start_ball_stays_clear_of_faces_and_the_fsi_zone) {
  EXPECT_THAT(
      errors_of(octant(kSphere, "{handoff_radius: 0.21}")),
      ElementsAre(HasSubstr("solver.afdmp.spherical.handoff_radius: the ball of 1.25 x "
                            "handoff_radius = 0.2625 m around the charge centre [0, 0, 0] meets "
                            "the x_upper face at 0.25 m (only symmetry planes through the centre "
                            "may); expected handoff_radius <= 0.2 m"),
                  HasSubstr("meets the y_upper face"), HasSubstr("meets the z_upper face")));
  const std::string off_centre =
      "charges:\n  - {name: c, material: tnt, shape: {sphere: {center: [0.04, 0.1, 0.1], "
      "radius: 0.0125}}, detonation_point: [0.04, 0.1, 0.1]}\n";
  expect_one(octant(off_centre, kHandoff), "solver.afdmp.spherical.handoff_radius",
             "meets the x_lower face at 0.04 m");
  expect_one(octant(kSphere, kHandoff,
                    "zones:\n  mpm: {lower: [0.04, 0, 0], upper: [0.25, 0.25, 0.25], "
                    "activation_pressure: 2.0e5}\n"),
             "solver.afdmp.spherical.handoff_radius",
             "meets zones.mpm at 0.04 m; expected handoff_radius <= 0.032 m");
}

TEST(AfdmpChecks, Spherical_start_ball_holds_only_the_background) {
  const std::string air =
      "bodies:\n  - {name: air, material: air, density: 1.225, specific_internal_energy: "
      "2.0685e5, particles_per_axis: 1,\n     shape: {box: {lower: [0, 0, 0], upper: [0.25, "
      "0.25, 0.25]}}}\n";
  EXPECT_NO_THROW(parse_scene(octant(kSphere + air, kHandoff), "v4.yaml"));
  const std::string dense =
      "bodies:\n  - {name: dense, material: air, density: 2.0, specific_internal_energy: "
      "2.0685e5,\n     shape: {sphere: {center: [0.06, 0, 0], radius: 0.02}}}\n";
  expect_one(octant(kSphere + dense, kHandoff), "bodies[0]",
             "meets the ball of 1.25 x handoff_radius = 0.05 m around the charge centre [0, 0, "
             "0]; expected the material and state of `initial` there");
}

TEST(AfdmpChecks, Spherical_start_is_afdmp_only) {
  std::string scene = octant(kSphere, kHandoff);
  scene.replace(scene.find("method: afdmp"), 13, "method: mpm");
  expect_one(scene, "solver.afdmp.start",
             "spherical is used only by solver.method afdmp; remove it or choose afdmp");
}

}  // namespace
}  // namespace mpfd::config::test
