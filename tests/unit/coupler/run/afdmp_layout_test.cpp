// The AFDMP geometry and Setup regions (coupler/run/afdmp_layout.hpp, design §3.2).
#include "coupler/run/afdmp_layout.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::HasSubstr;

// T §3.4.4 (V5): half domain x in [-0.5, 0.5], y in [0, 0.5] m, h = 1 mm; TNT
// r = 50 mm at the origin; steel plate x in [0.35, 0.37], y in [0, 0.25]; FSI
// zone x in [0.30, 0.5]. `fsi`, `charge` and `plate` replace those parts.
struct V5 {
  std::string fsi =
      "  mpm: {lower: [0.30, 0, 0], upper: [0.5, 0.5, 0.001], activation_pressure: 2.0e5}\n";
  std::string charge =
      "{cylinder: {base: [0, 0, 0], axis: [0, 0, 1], radius: 0.05, length: 0.001}}";
  std::string plate = "{box: {lower: [0.35, 0, 0], upper: [0.37, 0.25, 0.001]}}";

  [[nodiscard]] std::string text() const {
    return "name: v5\ntime: {end: 3.0e-4}\n"
           "domain: {lower: [-0.5, 0, 0], upper: [0.5, 0.5, 0.001], cells: [1000, 500, 1]}\n"
           "materials:\n"
           "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
           "  tnt:\n"
           "    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: "
           "0.3,"
           " E0: 6.993e9}\n"
           "    explosive: {detonation_velocity: 6930}\n"
           "  steel:\n"
           "    eos: {type: mie_gruneisen, rho0: 7890, C0: 4569, S: 1.49, gamma0: 2.17}\n"
           "    strength: {type: elastic, shear_modulus: 8.18e10}\n"
           "initial: {material: air, density: 1.225, pressure: 1.0e5}\n"
           "bodies:\n"
           "  - {name: air, material: air, density: 1.225, pressure: 1.0e5, particles_per_axis: "
           "1,\n"
           "     shape: {box: {lower: [-0.5, 0, 0], upper: [0.5, 0.5, 0.001]}}}\n"
           "  - {name: plate, material: steel, density: 7890, pressure: 0, shape: " +
           plate +
           "}\n"
           "charges:\n"
           "  - {name: charge, material: tnt, detonation_point: [0, 0, 0.0005], shape: " +
           charge +
           "}\n"
           "output: {interval: 1.0e-4}\nsolver: {method: afdmp}\n" +
           (fsi.empty() ? "" : "zones:\n" + fsi);
  }
};

config::Scene parse(const V5& v5) {
  return config::parse_scene(v5.text(), "v5.yaml");
}

/// The error of loading the scene and laying it out, or "no error".
std::string layout_error(const V5& v5) {
  try {
    (void)make_afdmp_layout(parse(v5));
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(AfdmpLayout, V5Boxes) {
  const AfdmpLayout l = make_afdmp_layout(parse(V5{}));
  EXPECT_EQ(l.dimension, 2);
  EXPECT_EQ(l.face_axis, 0);
  EXPECT_EQ(l.face_side, 1);
  EXPECT_EQ(box_text(l.all_cells), "[0, 1000) x [0, 500) x [0, 1)");
  // The face at x = 0.30 m is node 800.
  EXPECT_EQ(box_text(*l.fsi_cells), "[800, 1000) x [0, 500) x [0, 1)");
  EXPECT_EQ(box_text(l.fluid_cells), "[0, 800) x [0, 500) x [0, 1)");
  EXPECT_EQ(box_text(*l.watch_cells), "[798, 800) x [0, 500) x [0, 1)");
  // The charge's box x, y in [-0.05, 0.05] m: cells [450, 550) x [0, 50), grown by one.
  EXPECT_EQ(box_text(l.charge_cells), "[449, 551) x [0, 51) x [0, 1)");
  EXPECT_EQ(*l.activation_pressure, 2.0e5);
  const handoff::CellBox fluid = to_cell_box(l.fluid_cells);
  EXPECT_EQ(fluid.hi, (grid::Index3{800, 500, 1}));
}

TEST(AfdmpLayout, FsiZoneBelowItsFaceMirrorsTheBoxes) {
  V5 v5;
  v5.fsi = "  mpm: {lower: [-0.5, 0, 0], upper: [-0.3, 0.5, 0.001], activation_pressure: 2.0e5}\n";
  v5.plate = "{box: {lower: [-0.37, 0, 0], upper: [-0.35, 0.25, 0.001]}}";
  const AfdmpLayout l = make_afdmp_layout(parse(v5));
  EXPECT_EQ(l.face_side, -1);
  EXPECT_EQ(box_text(l.fluid_cells), "[200, 1000) x [0, 500) x [0, 1)");
  EXPECT_EQ(box_text(*l.watch_cells), "[200, 202) x [0, 500) x [0, 1)");
}

TEST(AfdmpLayout, SetupRegionsOfTheDesignTable) {
  const AfdmpLayout l = make_afdmp_layout(parse(V5{}));
  const AfdmpRegions r = afdmp_setup_regions(l, AfdmpStart::mpm);
  std::vector<std::string> fdm;
  for (const auto& region : r.fdm) fdm.push_back(region.name());
  EXPECT_THAT(fdm,
              ::testing::ElementsAre("all_cells", "all_tracers", "fluid_cells", "fluid_tracers",
                                     "fsi_watch", "fsi_cells", "audit_cells"));
  std::vector<std::string> mpm;
  for (const auto& region : r.mpm) mpm.push_back(region.name());
  EXPECT_THAT(mpm, ::testing::ElementsAre("fluid_particles", "fsi_particles", "charge_particles",
                                          "audit_particles"));
  EXPECT_EQ(r.fdm[1].kind(), v1::REGION_KIND_TRACERS);
  EXPECT_EQ(r.fdm[4].box().lo(0), 798);
  EXPECT_EQ(r.fdm[4].quantities_size(), 1);
  EXPECT_EQ(r.fdm[4].quantities(0), "pressure");
  EXPECT_EQ(r.fdm[2].quantities_size(), 8);
  EXPECT_EQ(r.mpm[0].kind(), v1::REGION_KIND_PARTICLES);
  EXPECT_EQ(r.mpm[0].box().hi(0), 800);
  EXPECT_EQ(r.mpm[2].box().lo(0), 449);
  // The run-long audit's: the whole grid with the outflow ledgers (afdmp_audit.hpp).
  EXPECT_EQ(r.fdm[6].box().hi(0), 1000);
  EXPECT_EQ(r.fdm[6].quantities_size(), 6);
  EXPECT_EQ(r.mpm[3].box().hi(0), 1000);
  EXPECT_EQ(r.mpm[3].quantities(3), "outflow_mass");

  // start = spherical: no phase-1 trigger on the MPM.
  const AfdmpRegions s = afdmp_setup_regions(l, AfdmpStart::spherical);
  EXPECT_EQ(s.mpm.size(), 3u);
  // A solver without boundary_outflow gets no outflow_* (proto/README.md §14).
  const AfdmpRegions v1_0 = afdmp_setup_regions(l, AfdmpStart::mpm, {.fdm = false, .mpm = true});
  EXPECT_EQ(v1_0.fdm[6].quantities_size(), 3);
  EXPECT_EQ(v1_0.mpm[3].quantities_size(), 6);
}

TEST(AfdmpLayout, WithoutFsiZoneTheFluidIsTheWholeGrid) {
  V5 v5;
  v5.fsi.clear();
  v5.plate = "{box: {lower: [0.35, 0, 0], upper: [0.37, 0.25, 0.001]}}";
  std::string text = v5.text();
  // No structure without an FSI zone: the plate becomes air.
  text.replace(text.find("material: steel, density: 7890, pressure: 0"), 43,
               "material: air, density: 1.225, pressure: 1e5");
  const AfdmpLayout l = make_afdmp_layout(config::parse_scene(text, "v3.yaml"));
  EXPECT_FALSE(l.fsi_cells.has_value());
  EXPECT_FALSE(l.watch_cells.has_value());
  EXPECT_EQ(box_text(l.fluid_cells), box_text(l.all_cells));
  const AfdmpRegions r = afdmp_setup_regions(l, AfdmpStart::mpm);
  EXPECT_EQ(r.fdm.size(), 3u);  // all_cells, all_tracers, audit_cells
  EXPECT_EQ(r.mpm.size(), 3u);  // fluid_particles, charge_particles, audit_particles
  EXPECT_TRUE(afdmp_setup_regions(l, AfdmpStart::spherical).mpm.empty());
}

TEST(AfdmpLayout, RefusesAnFsiZoneWithTwoInnerFaces) {
  V5 v5;
  v5.fsi = "  mpm: {lower: [0.3, 0, 0], upper: [0.4, 0.5, 0.001], activation_pressure: 2.0e5}\n";
  // The scene check refuses it first, naming file, line and key (config/scene_checks_afdmp).
  EXPECT_THAT(layout_error(v5), HasSubstr("zones.mpm: expected an FSI zone with exactly one face "
                                          "inside the domain"));
}

TEST(AfdmpLayout, RefusesAChargeInTheFsiZone) {
  V5 v5;
  v5.charge = "{cylinder: {base: [0.32, 0.1, 0], axis: [0, 0, 1], radius: 0.05, length: 0.001}}";
  EXPECT_THAT(layout_error(v5), HasSubstr("charges[0].shape: expected a charge outside zones.mpm"));
}

TEST(AfdmpLayout, RefusesABodyWithStrengthOutsideTheFsiZone) {
  V5 v5;
  v5.plate = "{box: {lower: [0.25, 0, 0], upper: [0.27, 0.25, 0.001]}}";
  EXPECT_THAT(layout_error(v5),
              HasSubstr("bodies[1].shape: expected a body with a strength model inside zones.mpm"));
}

TEST(AfdmpLayout, RefusesAnFsiZoneWithoutActivationPressure) {
  V5 v5;
  v5.fsi = "  mpm: {lower: [0.30, 0, 0], upper: [0.5, 0.5, 0.001]}\n";
  EXPECT_THAT(layout_error(v5), HasSubstr("activation_pressure"));
}

}  // namespace
}  // namespace mpfd::coupler
