// Broken scenes and the exact messages they get: file, line, column, key path,
// what was expected and what was found. Users fix scenes from these messages
// alone, so each part is asserted.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "common/config/scene_loader.hpp"
#include "tests/unit/common/config/scene_test_support.hpp"

namespace mpfd::config::test {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

// kMinimalScene with its first `from` replaced by `to` (lines keep their numbers).
std::string with(const std::string& from, const std::string& to) {
  std::string s = kMinimalScene;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

TEST(SceneErrors, Out_of_range_value_names_file_line_column_key_rule_and_value) {
  const std::string scene = R"(name: tube
time: {end: 1.0e-3}
domain: {lower: [0, 0, 0], upper: [1, 0.1, 0.1], cells: [10, 1, 1]}
materials:
  air:
    eos:
      type: ideal_gas
      gamma: 0.9
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
output: {interval: 1.0e-4}
)";
  EXPECT_THAT(
      errors_of(scene),
      ElementsAre("scene.yaml:8:14: materials.air.eos.gamma: expected a number > 1, got 0.9"));
}

TEST(SceneErrors, Misspelt_key_suggests_the_nearest_and_the_required_key_is_missing) {
  EXPECT_THAT(errors_of(with("gamma: 1.4", "gama: 1.4")),
              ElementsAre("scene.yaml:5:14: materials.air.eos.gamma: required key is missing; "
                          "expected a number > 1",
                          "scene.yaml:5:32: materials.air.eos.gama: unknown key; did you mean "
                          "'gamma'? (allowed here: type, gamma)"));
}

TEST(SceneErrors, Unknown_key_without_a_near_match_lists_the_allowed_keys) {
  EXPECT_THAT(errors_of(with("{end: 1.0e-3}", "{end: 1.0e-3, colour: red}")),
              ElementsAre("scene.yaml:2:21: time.colour: unknown key (allowed here: end, cfl, "
                          "max_steps)"));
}

TEST(SceneErrors, Missing_section_is_reported_at_the_map_that_lacks_it) {
  EXPECT_THAT(errors_of(with("time: {end: 1.0e-3}\n", "")),
              ElementsAre("scene.yaml:1:1: time: required key is missing; expected a map"));
}

TEST(SceneErrors, Text_where_a_number_belongs) {
  EXPECT_THAT(errors_of(with("end: 1.0e-3", "end: soon")),
              ElementsAre("scene.yaml:2:13: time.end: expected a number > 0, got soon"));
  EXPECT_THAT(errors_of(with("end: 1.0e-3", "end: \"1.0e-3\"")),
              ElementsAre("scene.yaml:2:13: time.end: expected a number > 0, got \"1.0e-3\" (a "
                          "quoted string)"));
}

TEST(SceneErrors, Switch_power_outside_1_to_4_names_the_key_and_the_range) {
  const std::string output = "output: {interval: 1.0e-4}\n";
  for (const std::string power : {"0", "5", "1.5"})
    EXPECT_THAT(errors_of(with(
                    output, output + "solver: {fdm: {viscosity_switch_power: " + power + "}}\n")),
                ElementsAre("scene.yaml:8:40: solver.fdm.viscosity_switch_power: expected an "
                            "integer in [1, 4], got " +
                            power));
}

TEST(SceneErrors, Scalar_where_a_point_belongs) {
  EXPECT_THAT(errors_of(with("lower: [0, 0, 0]", "lower: 0")),
              ElementsAre("scene.yaml:3:17: domain.lower: expected a list of 3 numbers, got 0"));
}

TEST(SceneErrors, List_of_the_wrong_length) {
  EXPECT_THAT(errors_of(with("cells: [10, 1, 1]", "cells: [10, 1]")),
              ElementsAre("scene.yaml:3:57: domain.cells: expected a list of 3 integers >= 1, "
                          "got a list of 2 items"));
}

TEST(SceneErrors, Bad_list_item_is_named_by_its_index) {
  EXPECT_THAT(errors_of(with("cells: [10, 1, 1]", "cells: [10, 0, 1.5]")),
              ElementsAre("scene.yaml:3:62: domain.cells[1]: expected an integer >= 1, got 0",
                          "scene.yaml:3:65: domain.cells[2]: expected an integer >= 1, got 1.5"));
}

TEST(SceneErrors, Map_where_a_value_belongs_and_nothing_where_a_value_belongs) {
  EXPECT_THAT(errors_of(with("density: 1.225", "density: {value: 1.225}")),
              ElementsAre("scene.yaml:6:35: initial.density: expected a number > 0, got a map"));
  EXPECT_THAT(errors_of(with("{end: 1.0e-3}", "{end: }")),
              ElementsAre("scene.yaml:2:8: time.end: expected a number > 0, got nothing"));
}

TEST(SceneErrors, Unknown_word_lists_the_allowed_words_and_suggests_one) {
  EXPECT_THAT(errors_of(kMinimalScene + "boundaries: {x_upper: walls}\n"),
              ElementsAre("scene.yaml:8:23: boundaries.x_upper: expected one of: outflow, wall, "
                          "symmetry, non_reflecting, got walls; did you mean 'wall'?"));
}

TEST(SceneErrors, Unknown_eos_type_suggests_a_known_one) {
  EXPECT_THAT(errors_of(with("type: ideal_gas", "type: idealgas")),
              ElementsAre("scene.yaml:5:21: materials.air.eos.type: expected one of: ideal_gas, "
                          "jwl, mie_gruneisen, polynomial, got idealgas; did you mean "
                          "'ideal_gas'?"));
}

TEST(SceneErrors, Planned_strength_model_is_not_yet_supported) {
  EXPECT_THAT(errors_of(with("gamma: 1.4}", "gamma: 1.4}, strength: {type: hjc}")),
              ElementsAre("scene.yaml:5:62: materials.air.strength.type: 'hjc' is not yet "
                          "supported; expected one of: none, elastic, johnson_cook"));
}

TEST(SceneErrors, Jwl_exponents_in_the_wrong_order) {
  const std::string tnt =
      "\n  tnt: {eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 0.95, R2: 4.15, "
      "omega: 0.3, E0: 6.993e9}}";
  EXPECT_THAT(errors_of(with("gamma: 1.4}}", "gamma: 1.4}}" + tnt)),
              ElementsAre("scene.yaml:6:65: materials.tnt.eos.R1: expected R1 > R2, got R1 = "
                          "0.95 <= R2 = 4.15"));
}

TEST(SceneErrors, Duplicate_keys_and_duplicate_material_names_point_at_the_first) {
  EXPECT_THAT(errors_of(with("{end: 1.0e-3}", "{end: 1.0e-3, end: 2.0e-3}")),
              ElementsAre("scene.yaml:2:21: time.end: duplicate key (first at line 2)"));
  EXPECT_THAT(errors_of(with("gamma: 1.4}}",
                             "gamma: 1.4}}\n  air: {eos: {type: ideal_gas, "
                             "gamma: 1.3}}")),
              ElementsAre("scene.yaml:6:3: materials.air: duplicate name (first at line 5)"));
}

TEST(SceneErrors, Pressure_and_energy_are_exclusive_and_one_is_needed) {
  EXPECT_THAT(errors_of(with("density: 1.225,", "density: 1.225, pressure: 1.0e5,")),
              ElementsAre("scene.yaml:6:10: initial: expected exactly one of the keys pressure "
                          "and specific_internal_energy"));
  EXPECT_THAT(errors_of(with(", specific_internal_energy: 2.0685e5", "")),
              ElementsAre("scene.yaml:6:10: initial: expected exactly one of the keys pressure "
                          "and specific_internal_energy"));
}

TEST(SceneErrors, Shape_has_exactly_one_known_kind) {
  const std::string body = "bodies:\n  - {name: b, material: air, density: 1, pressure: 1, shape: ";
  EXPECT_THAT(errors_of(kMinimalScene + body + "{spere: {center: [0, 0, 0], radius: 1}}}\n"),
              ElementsAre("scene.yaml:9:63: bodies[0].shape.spere: unknown key; did you mean "
                          "'sphere'? (allowed here: box, sphere, cylinder, union, difference)"));
  EXPECT_THAT(
      errors_of(kMinimalScene + body +
                "{sphere: {center: [0, 0, 0], radius: 1}, box: {lower: [0, 0, 0], upper: [1, 1, "
                "1]}}}\n"),
      ElementsAre("scene.yaml:9:62: bodies[0].shape: expected a map with exactly one key: box, "
                  "sphere, cylinder, union, difference, got a map"));
}

TEST(SceneErrors, Shape_geometry_is_checked) {
  const std::string body = "bodies:\n  - {name: b, material: air, density: 1, pressure: 1, shape: ";
  EXPECT_THAT(
      errors_of(kMinimalScene + body + "{box: {lower: [0, 0, 0], upper: [1, 0, 1]}}}\n"),
      ElementsAre("scene.yaml:9:94: bodies[0].shape.box.upper: expected upper > lower along y, "
                  "got 0 <= 0"));
  EXPECT_THAT(errors_of(kMinimalScene + body +
                        "{cylinder: {base: [0, 0, 0], axis: [0, 0, 0], radius: 1, length: 1}}}\n"),
              ElementsAre("scene.yaml:9:97: bodies[0].shape.cylinder.axis: expected a nonzero "
                          "direction, got [0, 0, 0]"));
  EXPECT_THAT(errors_of(kMinimalScene + body +
                        "{difference: [{sphere: {center: [0, 0, 0], radius: 1}}]}}\n"),
              ElementsAre("scene.yaml:9:75: bodies[0].shape.difference: expected a list of 2 or "
                          "more shapes, got a list of 1 item"));
}

TEST(SceneErrors, Yaml_syntax_error_gives_its_line) {
  EXPECT_THAT(errors_of("name: tube\ntime: {end: 1.0e-3\ndomain: {}\n"),
              ElementsAre(HasSubstr("scene.yaml:3:")));
  EXPECT_THAT(errors_of("name: tube\ntime: {end: 1.0e-3\ndomain: {}\n"),
              ElementsAre(HasSubstr("YAML syntax error")));
}

TEST(SceneErrors, Empty_file_expects_the_top_level_map) {
  EXPECT_THAT(errors_of(""), ElementsAre("scene.yaml:1:1: expected a map with keys: name, time, "
                                         "domain, zones, materials, initial, bodies, charges, "
                                         "boundaries, gauges, output, solver, got nothing"));
}

TEST(SceneErrors, Every_error_of_a_file_is_reported_at_once_in_file_order) {
  const std::string file = MPFD_SOURCE_DIR "/tests/unit/common/config/scenes/many_errors.yaml";
  try {
    load_scene(file);
    FAIL() << "many_errors.yaml parsed";
  } catch (const SceneError& e) {
    const std::string f = file + ":";
    EXPECT_EQ(std::string(e.what()),
              f +
                  "4:1: colour: unknown key (allowed here: name, time, domain, zones, materials, "
                  "initial, bodies, charges, boundaries, gauges, output, solver)\n" +
                  f + "6:8: time.end: expected a number > 0, got -1\n" + f +
                  "7:8: time.cfl: expected a number in (0, 1], got 1.5\n" + f +
                  "20:11: materials.tnt.eos.E0: expected a number > 0, got 0\n" + f +
                  "25:21: output.fields[1]: expected one of: density, velocity, pressure, "
                  "specific_internal_energy, sound_speed, material, volume_fraction, "
                  "burn_fraction, got presure; did you mean 'pressure'?");
  }
}

TEST(SceneErrors, Missing_file_names_the_file) {
  EXPECT_THROW(
      {
        try {
          load_scene("no/such/scene.yaml");
        } catch (const SceneError& e) {
          EXPECT_EQ(std::string(e.what()),
                    "no/such/scene.yaml: cannot open the scene file: No such file or directory");
          throw;
        }
      },
      SceneError);
}

}  // namespace
}  // namespace mpfd::config::test
