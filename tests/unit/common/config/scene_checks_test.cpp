// Checks that span sections: references to materials, unique names, points,
// shapes and zones against the domain and its grid, the solver method against
// the zones. Messages point at the key that is wrong.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "common/config/scene_loader.hpp"
#include "tests/unit/common/config/scene_test_support.hpp"

namespace mpfd::config::test {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

// A 2D scene, 1 m x 1 m, cells of 10 mm, with air and TNT; ten lines, so the
// sections the tests append start at line 11.
const std::string kBlast = R"(name: blast
time: {end: 1.0e-4}
domain: {lower: [0, 0, 0], upper: [1, 1, 0.01], cells: [100, 100, 1]}
materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
  tnt:
    eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
output: {interval: 1.0e-5}
)";

// kBlast with output.fields set to `list`.
std::string fields(const std::string& list) {
  std::string s = kBlast;
  const std::string from = "{interval: 1.0e-5}";
  return s.replace(s.find(from), from.size(), "{interval: 1.0e-5, fields: " + list + "}");
}

const std::string kBall = "shape: {sphere: {center: [0.5, 0.5, 0], radius: 0.05}}";

TEST(SceneChecks, Undefined_material_suggests_a_defined_one) {
  EXPECT_THAT(errors_of(kBlast + "bodies:\n  - {name: b, material: ari, density: 1, pressure: 1, " +
                        kBall + "}\n"),
              ElementsAre("scene.yaml:12:25: bodies[0].material: no material named 'ari'; did "
                          "you mean 'air'? (defined: air, tnt)"));
}

TEST(SceneChecks, Non_reflecting_faces_are_mpm_only_and_the_normal_body_exists) {
  EXPECT_THAT(
      errors_of(kBlast + "boundaries: {y_upper: non_reflecting}\n"),
      ElementsAre("scene.yaml:11:23: boundaries.y_upper: non_reflecting is an MPM boundary (W "
                  "§2.4); expected outflow, wall or symmetry with solver.method other than "
                  "mpm"));
  EXPECT_THAT(
      errors_of(kBlast +
                "bodies:\n  - {name: plate, material: air, density: 1, "
                "pressure: 1, " +
                kBall + "}\nsolver: {method: mpm, mpm: {contact: {normal_body: plat}}}\n"),
      ElementsAre("scene.yaml:13:52: solver.mpm.contact.normal_body: no body or charge named "
                  "'plat'; did you mean 'plate'? (defined: plate)"));
  EXPECT_NO_THROW(parse_scene(
      kBlast + "boundaries: {y_upper: non_reflecting}\nsolver: {method: mpm}\n", "scene.yaml"));
}

TEST(SceneChecks, Reference_pressure_needs_an_mpm) {
  const std::string options = "mpm: {reference_pressure: 101325}}\n";
  EXPECT_THAT(errors_of(kBlast + "solver: {method: fdm, " + options),
              ElementsAre(::testing::HasSubstr(
                  "solver.mpm.reference_pressure: expected 0 with solver.method fdm")));
  EXPECT_NO_THROW(parse_scene(kBlast + "solver: {method: mpm, " + options, "scene.yaml"));
}

TEST(SceneChecks, Usavg_is_not_with_contact) {
  EXPECT_THAT(errors_of(kBlast + "solver: {method: mpm, mpm: {update: usavg, contact: {}}}\n"),
              ElementsAre(::testing::HasSubstr(
                  "solver.mpm.update: usavg is not supported with solver.mpm.contact yet")));
  const Scene s = parse_scene(kBlast + "solver: {method: mpm, mpm: {update: usavg}}\n", "s.yaml");
  EXPECT_EQ(s.solver.mpm.update, MpmUpdate::usavg);
}

TEST(SceneChecks, Charge_material_must_be_an_explosive) {
  EXPECT_THAT(errors_of(kBlast + "charges:\n  - {name: c, material: air, " + kBall +
                        ", detonation_point: [0.5, 0.5, 0]}\n"),
              ElementsAre("scene.yaml:12:25: charges[0].material: material 'air' cannot "
                          "detonate; expected a material with eos type jwl and an `explosive` "
                          "section"));
}

TEST(SceneChecks, Program_burn_needs_a_detonation_point_and_instantaneous_has_none) {
  EXPECT_THAT(errors_of(kBlast + "charges:\n  - {name: c, material: tnt, " + kBall + "}\n"),
              ElementsAre("scene.yaml:12:5: charges[0].detonation_point: required key is "
                          "missing; expected a list of 3 numbers (burn is program)"));
  EXPECT_THAT(errors_of(kBlast + "charges:\n  - {name: c, material: tnt, " + kBall +
                        ", burn: instantaneous, detonation_point: [0.5, 0.5, 0]}\n"),
              ElementsAre("scene.yaml:12:125: charges[0].detonation_point: not used with burn: "
                          "instantaneous; remove it"));
}

TEST(SceneChecks, Bodies_and_charges_share_one_namespace_gauges_another) {
  const std::string scene =
      kBlast + "bodies:\n  - {name: hot, material: air, density: 2, pressure: 1e5, " + kBall +
      "}\n" + "charges:\n  - {name: hot, material: tnt, " + kBall +
      ", detonation_point: [0.5, 0.5, 0]}\n" +
      "gauges:\n  - {name: hot, position: [0.1, 0.1, 0]}\n" +
      "  - {name: g, position: [0.2, 0.1, 0]}\n" + "  - {name: g, position: [0.3, 0.1, 0]}\n";
  EXPECT_THAT(errors_of(scene),
              ElementsAre("scene.yaml:14:12: charges[0].name: duplicate name 'hot' (also "
                          "bodies[0])",
                          "scene.yaml:18:12: gauges[2].name: duplicate name 'g' (also gauges[1])"));
}

TEST(SceneChecks, Gauges_and_detonation_points_lie_inside_the_domain) {
  EXPECT_THAT(errors_of(kBlast + "gauges: [{name: far, position: [1.5, 0.5, 0]}]\n"),
              ElementsAre("scene.yaml:11:32: gauges[0].position: expected a point inside the "
                          "domain [0, 0, 0] to [1, 1, 0.01], got [1.5, 0.5, 0]"));
  EXPECT_THAT(errors_of(kBlast + "charges:\n  - {name: c, material: tnt, " + kBall +
                        ", detonation_point: [0.5, -0.1, 0]}\n"),
              ElementsAre("scene.yaml:12:104: charges[0].detonation_point: expected a point "
                          "inside the domain [0, 0, 0] to [1, 1, 0.01], got [0.5, -0.1, 0]"));
}

TEST(SceneChecks, Body_entirely_outside_is_an_error_but_a_clipped_body_is_not) {
  const std::string body = "bodies:\n  - {name: b, material: air, density: 2, pressure: 1e5, ";
  EXPECT_THAT(errors_of(kBlast + body + "shape: {sphere: {center: [2, 0.5, 0], radius: 0.5}}}\n"),
              ElementsAre("scene.yaml:12:64: bodies[0].shape: expected a shape overlapping the "
                          "domain [0, 0, 0] to [1, 1, 0.01], got one entirely outside"));
  // A quarter of a charge at a corner, as symmetric scenes use: accepted.
  EXPECT_NO_THROW(parse_scene(
      kBlast + "charges:\n  - {name: c, material: tnt, detonation_point: [0, 0, 0], shape: "
               "{sphere: {center: [0, 0, 0], radius: 0.05}}}\n",
      "scene.yaml"));
}

TEST(SceneChecks, Output_field_listed_twice) {
  EXPECT_THAT(errors_of(fields("[density, pressure, density]")),
              ElementsAre("scene.yaml:10:56: output.fields[2]: listed twice"));
}

TEST(SceneChecks, An_error_in_a_material_does_not_cascade_into_its_users) {
  std::string scene =
      kBlast + "bodies:\n  - {name: b, material: tnt, density: 1630, pressure: 0, " + kBall + "}\n";
  scene.replace(scene.find("omega: 0.3"), 10, "omega: -1");
  EXPECT_THAT(errors_of(scene),
              ElementsAre("scene.yaml:7:84: materials.tnt.eos.omega: expected a number > 0, got "
                          "-1"));
}

// CFDMP after thesis V6 (T §4.4.2): domain [-180, 160] x [0, 500] mm, h = 2 mm,
// FDM [-180, 120], MPM [110, 160], handshake w = 5 cells.
std::string cfdmp(const std::string& zones, const std::string& method = "cfdmp") {
  return R"(name: v6
time: {end: 1.0e-3}
domain: {lower: [-0.18, 0, 0], upper: [0.16, 0.5, 0.002], cells: [170, 250, 1]}
materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
output: {interval: 1.0e-5}
solver: {method: )" +
         method + "}\nzones:\n" + zones;
}

const std::string kV6Zones = R"(  fdm: {lower: [-0.18, 0, 0], upper: [0.12, 0.5, 0.002]}
  mpm: {lower: [0.11, 0, 0], upper: [0.16, 0.5, 0.002], activation_pressure: 2.0e5}
  handshake_width: 5
)";

TEST(SceneChecks, Thesis_V6_zones_are_accepted) {
  const Scene s = parse_scene(cfdmp(kV6Zones), "v6.yaml");
  ASSERT_TRUE(s.zones && s.zones->fdm && s.zones->mpm);
  EXPECT_EQ(s.zones->mpm->activation_pressure, 2.0e5);
  EXPECT_EQ(s.zones->handshake_width, 5);
}

TEST(SceneChecks, A_bad_activation_pressure_is_refused) {
  for (const std::string bad : {"-1.0", ".nan", ".inf", "high", "[2.0e5]"}) {
    std::string zones = kV6Zones;
    zones.replace(zones.find("2.0e5"), 5, bad);
    const auto errors = errors_of(cfdmp(zones));
    ASSERT_EQ(errors.size(), 1U) << bad;
    EXPECT_THAT(errors[0], ::testing::HasSubstr("zones.mpm.activation_pressure")) << bad;
  }
}

TEST(SceneChecks, Zone_corners_lie_on_grid_lines) {
  std::string zones = kV6Zones;
  zones.replace(zones.find("0.12,"), 5, "0.121,");
  EXPECT_THAT(errors_of(cfdmp(zones)),
              ElementsAre("scene.yaml:10:38: zones.fdm.upper: expected coordinates on grid lines, "
                          "got x = 0.121 between 0.12 and 0.122 (cell size 0.002)"));
}

TEST(SceneChecks, Zones_overlap_by_the_handshake_width) {
  std::string zones = kV6Zones;
  zones.replace(zones.find("0.11,"), 5, "0.112,");
  EXPECT_THAT(errors_of(cfdmp(zones)),
              ElementsAre("scene.yaml:12:20: zones.handshake_width: expected the fdm and mpm zones "
                          "to overlap by at least handshake_width = 5 cells along x, got 4"));
}

// cfdmp(zones) with a body of steel (with a strength model, or without: a fluid) in
// `box` ("{lower: [...], upper: [...]}").
std::string with_steel_body(const std::string& zones, const std::string& box,
                            bool strength = true) {
  std::string scene = cfdmp(zones);
  const std::string air = "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n";
  scene.replace(
      scene.find(air), air.size(),
      air +
          "  steel:\n"
          "    eos: {type: mie_gruneisen, rho0: 7890, C0: 4569, S: 1.49, gamma0: 2.17}\n" +
          (strength ? "    strength: {type: elastic, shear_modulus: 8.18e10}\n" : ""));
  return scene + "bodies:\n  - {name: plate, material: steel, density: 7890, pressure: 1.0e5,\n" +
         "     shape: {box: " + box + "}}\n";
}

// A plate of 14 mm across the V6 domain from x = `x`.
std::string plate_from(double x) {
  return "{lower: [" + std::to_string(x) + ", 0, 0], upper: [" + std::to_string(x + 0.014) +
         ", 0.5, 0.002]}";
}

const auto kRefusedStructure = [](const std::string& beyond) {
  return AllOf(HasSubstr("bodies[0].shape: expected a body with a strength model in zones.mpm "
                         "at least 4 cells past zones.fdm (its 3 ghost layers and the cell whose "
                         "particles reach the ghost cells' outer nodes: " +
                         beyond + " m), got 'plate' (material 'steel')"),
               HasSubstr("the FDM holds no solid"));
};

TEST(SceneChecks, A_structure_lies_in_the_mpm_zone_beyond_the_fdm_zone_and_its_ghost_layers) {
  // V6: the FDM zone ends at x = 0.12 m, its 3 ghost layers at 0.126 m, and
  // the ghost cells' outer nodes (x = 0.126 m) gather the particles up to 0.128 m.
  EXPECT_NO_THROW((void)parse_scene(with_steel_body(kV6Zones, plate_from(0.128)), "scene.yaml"));
  // The node-sharing cell, the ghost layers, the handshake zone, the FDM alone.
  for (const double x : {0.127, 0.124, 0.112, -0.1})
    EXPECT_THAT(errors_of(with_steel_body(kV6Zones, plate_from(x))),
                ElementsAre(kRefusedStructure("x >= 0.128")))
        << "plate at x = " << x;
  const std::string fluid = with_steel_body(kV6Zones, plate_from(-0.1), false);
  EXPECT_NO_THROW((void)parse_scene(fluid, "scene.yaml"));
}

TEST(SceneChecks, A_structure_lies_beyond_the_ghost_layers_on_either_side_and_axis) {
  // The MPM zone below the FDM's along x: ghost layers and the node-sharing
  // cell down to x = -0.138 m.
  const std::string below = R"(  fdm: {lower: [-0.13, 0, 0], upper: [0.16, 0.5, 0.002]}
  mpm: {lower: [-0.18, 0, 0], upper: [-0.12, 0.5, 0.002]}
)";
  EXPECT_NO_THROW((void)parse_scene(with_steel_body(below, plate_from(-0.152)), "scene.yaml"));
  EXPECT_THAT(errors_of(with_steel_body(below, plate_from(-0.15))),
              ElementsAre(kRefusedStructure("x <= -0.138")));
  // Across y: the FDM zone up to y = 0.3 m, ghost layers and that cell to 0.308 m.
  const std::string across_y = R"(  fdm: {lower: [-0.18, 0, 0], upper: [0.16, 0.3, 0.002]}
  mpm: {lower: [-0.18, 0.29, 0], upper: [0.16, 0.5, 0.002]}
)";
  const auto slab_from = [](const std::string& y) {
    return "{lower: [-0.18, " + y + ", 0], upper: [0.16, 0.45, 0.002]}";
  };
  EXPECT_NO_THROW((void)parse_scene(with_steel_body(across_y, slab_from("0.308")), "scene.yaml"));
  EXPECT_THAT(errors_of(with_steel_body(across_y, slab_from("0.306"))),
              ElementsAre(kRefusedStructure("y >= 0.308")));
}

TEST(SceneChecks, Zones_lie_inside_the_domain) {
  std::string zones = kV6Zones;
  zones.replace(zones.find("0.16, 0.5"), 4, "0.17");
  EXPECT_THAT(errors_of(cfdmp(zones)),
              ElementsAre("scene.yaml:11:8: zones.mpm: expected a zone inside the domain [-0.18, "
                          "0, 0] to [0.16, 0.5, 0.002], got x from 0.11 to 0.17"));
}

TEST(SceneChecks, A_gauge_follows_the_material_only_where_the_MPM_keeps_particles) {
  const std::string follow = "gauges: [{name: g, position: [0.5, 0.5, 0], follow: material}]\n";
  EXPECT_THAT(errors_of(kBlast + "solver: {method: fdm}\n" + follow),
              ElementsAre(::testing::HasSubstr(
                  "gauges[0].follow: expected point with solver.method fdm (material follows an "
                  "MPM particle; the FDM has none), got material")));
  EXPECT_NO_THROW(parse_scene(kBlast + "solver: {method: mpm}\n" + follow, "scene.yaml"));
  EXPECT_EQ(parse_scene(kBlast + follow.substr(0, follow.find(", follow")) + "}]\n", "scene.yaml")
                .gauges[0]
                .follow,
            GaugeFollow::point);
  // CFDMP: inside zones.mpm (x >= 0.11) yes, in the FDM zone only no.
  EXPECT_NO_THROW(parse_scene(
      cfdmp(kV6Zones) + "gauges: [{name: g, position: [0.13, 0.1, 0.001], follow: material}]\n",
      "v6.yaml"));
  EXPECT_THAT(
      errors_of(cfdmp(kV6Zones) +
                "gauges: [{name: g, position: [0.0, 0.1, 0.001], follow: material}]\n"),
      ElementsAre(::testing::HasSubstr(
          "gauges[0].follow: expected point for a gauge outside zones.mpm (material follows an "
          "MPM particle, and only zones.mpm keeps its particles in every phase), got material at "
          "[0, 0.1, 0.001]")));
}

TEST(SceneChecks, Solver_method_and_zones_agree) {
  EXPECT_THAT(errors_of(cfdmp(kV6Zones, "fdm")),
              ElementsAre("scene.yaml:10:3: zones: not used by solver.method fdm or mpm (one "
                          "solver owns the whole domain); remove it or choose cfdmp or afdmp"));
  std::string only_mpm = kV6Zones;
  only_mpm.erase(0, only_mpm.find("  mpm"));
  EXPECT_THAT(errors_of(cfdmp(only_mpm)),
              ElementsAre("scene.yaml:8:18: solver.method: cfdmp needs both zones.fdm and "
                          "zones.mpm"));
}

}  // namespace
}  // namespace mpfd::config::test
