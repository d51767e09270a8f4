// The regions of proto §6 from a scene's zones (coupler/run/zone_layout.hpp).
#include "coupler/run/zone_layout.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::HasSubstr;

std::string scene_text(const std::string& domain, const std::string& zones,
                       const std::string& method = "cfdmp") {
  return "name: t\ntime: {end: 1.0e-3}\ndomain: " + domain +
         "\nmaterials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
         "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
         "output: {interval: 1.0e-4}\nsolver: {method: " +
         method + "}\nzones:\n" + zones;
}

// Thesis V6 (T §4.4.2): h = 2 mm, FDM [-180, 120] mm, MPM [110, 160] mm, w = 5.
TEST(ZoneLayout, Thesis_V6_regions) {
  const auto scene = config::parse_scene(
      scene_text("{lower: [-0.18, 0, 0], upper: [0.16, 0.5, 0.002], cells: [170, 250, 1]}",
                 "  fdm: {lower: [-0.18, 0, 0], upper: [0.12, 0.5, 0.002]}\n"
                 "  mpm: {lower: [0.11, 0, 0], upper: [0.16, 0.5, 0.002]}\n"
                 "  handshake_width: 5\n"),
      "v6.yaml");
  const ZoneLayout l = make_zone_layout(scene);
  EXPECT_EQ(l.dimension, 2);
  EXPECT_EQ(l.face_axis, 0);
  EXPECT_EQ(l.face_side, 1);
  // Face at x = 0.11 m = node 145; FDM zone ends at cell 150 (x = 0.12 m).
  EXPECT_EQ(box_text(l.strip_cells), "[144, 146) x [0, 250) x [0, 1)");
  EXPECT_EQ(box_text(l.deposit_cells), "[143, 145) x [0, 250) x [0, 1)");
  EXPECT_EQ(box_text(l.ghost_cells), "[150, 153) x [0, 250) x [0, 1)");
  EXPECT_EQ(box_text(l.ghost_nodes), "[150, 154) x [0, 251) x [0, 1)");
  EXPECT_EQ(box_text(l.interface_nodes), "[145, 146) x [0, 251) x [0, 1)");
  EXPECT_EQ(box_text(l.face_cells), "[145, 146) x [0, 250) x [0, 1)");
  EXPECT_EQ(box_text(l.fdm_owned), "[0, 145) x [0, 250) x [0, 1)");
  EXPECT_EQ(box_text(l.mpm_zone), "[145, 170) x [0, 250) x [0, 1)");
  // A uGIMP particle within its half-width of the face reaches node 144; cells 144 and
  // 143 (k-w, k-w-1) are the FDM's material around it.
  EXPECT_EQ(box_text(l.outer_nodes), "[144, 145) x [0, 251) x [0, 1)");
  EXPECT_EQ(box_text(l.beyond_cells), "[143, 144) x [0, 250) x [0, 1)");
  EXPECT_FALSE(mpm_reaches_outer_nodes(scene));  // linear, the default
}

TEST(ZoneLayout, Mpm_zone_below_the_face_mirrors_the_regions) {
  const auto scene = config::parse_scene(
      scene_text("{lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [100, 1, 1]}",
                 "  fdm: {lower: [0.3, 0, 0], upper: [1, 0.01, 0.01]}\n"
                 "  mpm: {lower: [0, 0, 0], upper: [0.36, 0.01, 0.01]}\n"),
      "mirror.yaml");
  const ZoneLayout l = make_zone_layout(scene);
  EXPECT_EQ(l.dimension, 1);
  EXPECT_EQ(l.face_side, -1);
  EXPECT_EQ(box_text(l.strip_cells), "[35, 37) x [0, 1) x [0, 1)");
  EXPECT_EQ(box_text(l.deposit_cells), "[36, 38) x [0, 1) x [0, 1)");
  EXPECT_EQ(box_text(l.ghost_cells), "[27, 30) x [0, 1) x [0, 1)");
  EXPECT_EQ(box_text(l.ghost_nodes), "[27, 31) x [0, 1) x [0, 1)");
  EXPECT_EQ(box_text(l.fdm_owned), "[36, 100) x [0, 1) x [0, 1)");
  EXPECT_EQ(box_text(l.face_cells), "[35, 36) x [0, 1) x [0, 1)");  // the inner strip cell
  EXPECT_EQ(box_text(l.outer_nodes), "[37, 38) x [0, 1) x [0, 1)");
  EXPECT_EQ(box_text(l.beyond_cells), "[37, 38) x [0, 1) x [0, 1)");
}

TEST(ZoneLayout, Gimp_and_cpgimp_reach_the_outer_nodes) {
  const std::string domain = "{lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [100, 1, 1]}";
  const std::string zones =
      "  fdm: {lower: [0, 0, 0], upper: [0.65, 0.01, 0.01]}\n"
      "  mpm: {lower: [0.6, 0, 0], upper: [1, 0.01, 0.01]}\n";
  for (const char* shape : {"linear", "gimp", "cpgimp"}) {
    const auto scene = config::parse_scene(
        scene_text(domain, zones, std::string("cfdmp, mpm: {shape_function: ") + shape + "}"),
        "shape.yaml");
    EXPECT_EQ(mpm_reaches_outer_nodes(scene), std::string(shape) != "linear") << shape;
  }
}

std::string layout_error(const std::string& text) {
  try {
    (void)make_zone_layout(config::parse_scene(text, "bad.yaml"));
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(ZoneLayout, Refuses_an_mpm_zone_with_two_inner_faces) {
  EXPECT_THAT(
      layout_error(scene_text("{lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [100, 1, 1]}",
                              "  fdm: {lower: [0, 0, 0], upper: [1, 0.01, 0.01]}\n"
                              "  mpm: {lower: [0.4, 0, 0], upper: [0.6, 0.01, 0.01]}\n")),
      HasSubstr("exactly one face inside the domain (the coupling face), found 2"));
}

TEST(ZoneLayout, Refuses_too_few_ghost_layers_inside_the_mpm_zone) {
  EXPECT_THAT(
      layout_error(scene_text("{lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [100, 1, 1]}",
                              "  fdm: {lower: [0, 0, 0], upper: [0.99, 0.01, 0.01]}\n"
                              "  mpm: {lower: [0.6, 0, 0], upper: [1, 0.01, 0.01]}\n")),
      HasSubstr("3 FDM ghost layers inside the MPM zone past the FDM zone's end"));
}

TEST(ZoneLayout, Refuses_a_scene_that_is_not_cfdmp) {
  EXPECT_THAT(layout_error("name: t\ntime: {end: 1}\n"
                           "domain: {lower: [0, 0, 0], upper: [1, 1, 1], cells: [10, 1, 1]}\n"
                           "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
                           "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
                           "output: {interval: 0.1}\n"),
              HasSubstr("needs solver.method cfdmp"));
}

}  // namespace
}  // namespace mpfd::coupler
