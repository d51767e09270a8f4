// Valid scenes: values arrive in the typed Scene unchanged and in SI, defaults
// fill what a scene leaves out, every scene in configs/ loads, and the
// checked-in reference is the schema's own output.
#include "common/config/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "tests/unit/common/config/scene_test_support.hpp"

namespace mpfd::config::test {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(SceneLoader, Thesis_air_round_trips_exactly) {
  const Scene s = parse_scene(kMinimalScene, "air.yaml");
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(std::get<eos::IdealGas>(s.materials[0].eos).gamma, 1.4);
  EXPECT_EQ(s.initial.material, "air");
  EXPECT_EQ(s.initial.density, 1.225);
  EXPECT_EQ(s.initial.specific_internal_energy, 2.0685e5);
  EXPECT_FALSE(s.initial.pressure.has_value());
}

TEST(SceneLoader, Defaults_fill_what_the_scene_leaves_out) {
  const Scene s = parse_scene(kMinimalScene, "air.yaml");
  EXPECT_FALSE(s.time.cfl.has_value());
  EXPECT_EQ(s.time.fdm_cfl(), 0.5);
  EXPECT_EQ(s.time.mpm_cfl(), 0.2);
  EXPECT_EQ(s.time.max_steps, 1000000);
  EXPECT_FALSE(s.zones.has_value());
  EXPECT_TRUE(std::holds_alternative<NoStrength>(s.materials[0].strength));
  EXPECT_FALSE(s.materials[0].explosive.has_value());
  EXPECT_EQ(s.initial.velocity, (Vec3{0, 0, 0}));
  EXPECT_TRUE(s.bodies.empty() && s.charges.empty() && s.gauges.empty());
  for (const BoundaryKind b : s.boundaries.faces) EXPECT_EQ(b, BoundaryKind::outflow);
  EXPECT_EQ(s.output.fields,
            (std::vector<Field>{Field::density, Field::velocity, Field::pressure}));
  EXPECT_FALSE(s.output.gauge_interval.has_value());
  EXPECT_EQ(s.solver.method, Method::fdm);
  EXPECT_EQ(s.solver.fdm.artificial_viscosity, 1.0);
  EXPECT_EQ(s.solver.fdm.viscosity_switch_power, 1);
  EXPECT_EQ(s.solver.mpm.shape_function, ShapeFunction::linear);
  EXPECT_EQ(s.solver.mpm.update, MpmUpdate::usavg);
  EXPECT_EQ(s.solver.mpm.gravity, (Vec3{0, 0, 0}));
  EXPECT_EQ(s.solver.mpm.shear_damping, 0.0);
  EXPECT_FALSE(s.solver.mpm.contact.has_value());
}

TEST(SceneLoader, Mpm_physics_keys_arrive_in_the_typed_scene) {
  const Scene s = parse_scene(
      kMinimalScene +
          "bodies:\n  - {name: clamp, material: air, density: 1, pressure: 1, fixed: true,\n"
          "     shape: {box: {lower: [0, 0, 0], upper: [0.1, 1, 1]}}}\n"
          "boundaries: {x_upper: non_reflecting}\n"
          "solver:\n  method: mpm\n  mpm: {gravity: [0, -9.81, 0], shear_damping: 0.1,\n"
          "        contact: {friction: 0.2, normal_body: clamp}}\n",
      "mpm.yaml");
  EXPECT_TRUE(s.bodies.at(0).fixed);
  EXPECT_EQ(s.boundaries[Face::x_upper], BoundaryKind::non_reflecting);
  EXPECT_EQ(s.solver.mpm.gravity, (Vec3{0, -9.81, 0}));
  EXPECT_EQ(s.solver.mpm.shear_damping, 0.1);
  ASSERT_TRUE(s.solver.mpm.contact.has_value());
  EXPECT_EQ(s.solver.mpm.contact->friction, 0.2);
  EXPECT_EQ(s.solver.mpm.contact->normal_body, "clamp");
  const Scene plain =
      parse_scene(kMinimalScene + "solver: {method: mpm, mpm: {contact: {}}}\n", "mpm.yaml");
  ASSERT_TRUE(plain.solver.mpm.contact.has_value());
  EXPECT_EQ(plain.solver.mpm.contact->friction, 0.0);
  EXPECT_FALSE(plain.solver.mpm.contact->normal_body.has_value());
}

// usavg is the default only where it runs: with contact a scene that leaves
// solver.mpm.update out gets musl; one that names it keeps its choice.
TEST(SceneLoader, Update_defaults_to_usavg_and_to_musl_with_contact) {
  const auto update_of = [](const std::string& mpm) {
    return parse_scene(kMinimalScene + "solver: {method: mpm, mpm: {" + mpm + "}}\n", "mpm.yaml")
        .solver.mpm.update;
  };
  EXPECT_EQ(update_of(""), MpmUpdate::usavg);
  EXPECT_EQ(update_of("contact: {}"), MpmUpdate::musl);
  EXPECT_EQ(update_of("contact: {}, update: usl"), MpmUpdate::usl);
  EXPECT_EQ(update_of("update: musl"), MpmUpdate::musl);
}

TEST(SceneLoader, Every_section_arrives_in_the_typed_scene) {
  const Scene s = parse_scene(R"(name: plate
time: {end: 2.0e-3, cfl: 0.4, max_steps: 1e5}
domain: {lower: [-0.5, 0, 0], upper: [0.5, 1, 0.01], cells: [100, 100, 1]}
materials:
  tnt:
    eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
  air: {eos: {type: ideal_gas, gamma: 1.4}}
  steel:
    eos: {type: mie_gruneisen, rho0: 7830, C0: 4569, S: 1.49, gamma0: 2.17}
    strength: {type: johnson_cook, A: 350e6, B: 275e6, n: 0.36, C: 0.022, m: 1.0,
               T_melt: 1811, specific_heat: 452, shear_modulus: 81.8e9, failure_strain: 0.3}
  water: {eos: {type: polynomial, rho0: 1000, A1: 2.2e9, B0: 0.28}}
initial: {material: air, density: 1.225, pressure: 1.0e5, velocity: [1, 2, 3]}
bodies:
  - name: plate
    material: steel
    density: 7830
    specific_internal_energy: 0
    particles_per_axis: 3
    shape: {union: [{box: {lower: [-0.1, 0.6, 0], upper: [0.1, 0.62, 0.01]}},
                    {cylinder: {base: [0, 0.62, 0], axis: [0, 1, 0], radius: 0.02, length: 0.01}}]}
charges:
  - {name: tnt, material: tnt, shape: {sphere: {center: [0, 0.25, 0], radius: 0.05}},
     detonation_point: [0, 0.25, 0]}
boundaries: {x_lower: symmetry, y_upper: wall}
gauges: [{name: g1, position: [0, 0.5, 0.005]}]
output: {interval: 1.0e-5, fields: [pressure, burn_fraction], gauge_interval: 1.0e-7}
solver: {method: mpm, fdm: {artificial_viscosity: 0.5, viscosity_switch_power: 2}, mpm: {shape_function: gimp, update: usl}}
)",
                              "plate.yaml");
  EXPECT_EQ(s.time.max_steps, 100000);
  EXPECT_EQ(s.domain.cells, (std::array<int, 3>{100, 100, 1}));
  ASSERT_EQ(s.materials.size(), 4u);  // file order: the output's material index
  EXPECT_EQ(s.materials[0].name, "tnt");
  EXPECT_EQ(s.materials[3].name, "water");
  const auto& jwl = std::get<eos::Jwl>(s.materials[0].eos);
  EXPECT_EQ(jwl.a, 371.2e9);
  EXPECT_EQ(jwl.r2, 0.95);
  EXPECT_EQ(jwl.detonation_energy, 6.993e9);
  EXPECT_EQ(s.materials[0].explosive->detonation_velocity, 6930);
  EXPECT_EQ(std::get<eos::MieGruneisen>(s.materials[2].eos).c0, 4569);
  const auto& jc = std::get<JohnsonCook>(s.materials[2].strength);
  EXPECT_EQ(jc.n, 0.36);
  EXPECT_EQ(jc.room_temperature, 293.0);
  EXPECT_EQ(jc.reference_strain_rate, 1.0);
  EXPECT_EQ(jc.failure_strain, 0.3);
  const auto& water = std::get<eos::Polynomial>(s.materials[3].eos);
  EXPECT_EQ(water.b0, 0.28);
  EXPECT_EQ(water.a2, 0.0);
  EXPECT_EQ(s.initial.pressure, 1.0e5);
  EXPECT_EQ(s.initial.velocity, (Vec3{1, 2, 3}));
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].state.material, "steel");
  EXPECT_EQ(s.bodies[0].particles_per_axis, 3);
  EXPECT_TRUE(contains(s.bodies[0].shape, {0.0, 0.625, 0.0}));  // in the cylinder
  EXPECT_FALSE(contains(s.bodies[0].shape, {0.09, 0.625, 0.0}));
  ASSERT_EQ(s.charges.size(), 1u);
  EXPECT_EQ(s.charges[0].burn, Burn::program);
  EXPECT_EQ(s.charges[0].detonation_point, (Vec3{0, 0.25, 0}));
  EXPECT_EQ(s.boundaries[Face::x_lower], BoundaryKind::symmetry);
  EXPECT_EQ(s.boundaries[Face::y_upper], BoundaryKind::wall);
  EXPECT_EQ(s.boundaries[Face::x_upper], BoundaryKind::outflow);
  EXPECT_EQ(s.gauges.at(0).name, "g1");
  EXPECT_EQ(s.output.fields, (std::vector<Field>{Field::pressure, Field::burn_fraction}));
  EXPECT_EQ(s.output.gauge_interval, 1.0e-7);
  EXPECT_EQ(s.solver.method, Method::mpm);
  EXPECT_EQ(s.solver.fdm.artificial_viscosity, 0.5);
  EXPECT_EQ(s.solver.fdm.viscosity_switch_power, 2);
  EXPECT_EQ(s.solver.mpm.shape_function, ShapeFunction::gimp);
  EXPECT_EQ(s.solver.mpm.update, MpmUpdate::usl);
}

std::vector<fs::path> config_scenes() {
  std::vector<fs::path> scenes;
  for (const auto& entry : fs::directory_iterator(kConfigs)) {
    if (entry.path().extension() == ".yaml") scenes.push_back(entry.path());
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

TEST(SceneLoader, Every_scene_in_configs_loads_and_teaches) {
  const auto scenes = config_scenes();
  EXPECT_GE(scenes.size(), 3u);
  for (const fs::path& file : scenes) {
    SCOPED_TRACE(file.string());
    EXPECT_NO_THROW(load_scene(file));
    const std::string text = read(file);
    EXPECT_TRUE(text.starts_with("# Description:")) << "the header block opens every scene";
    EXPECT_NE(text.find("\n# Sample run:"), std::string::npos);
  }
}

TEST(SceneLoader, Sod_scene_holds_the_classic_states) {
  const Scene s = load_scene(kConfigs / "sod.yaml");
  EXPECT_EQ(std::get<eos::IdealGas>(s.materials.at(0).eos).gamma, 1.4);
  EXPECT_EQ(s.initial.density, 0.125);
  EXPECT_EQ(s.initial.pressure, 0.1);
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].state.density, 1.0);
  EXPECT_EQ(s.bodies[0].state.pressure, 1.0);
  EXPECT_TRUE(contains(s.bodies[0].shape, {0.25, 0.005, 0.005}));
  EXPECT_FALSE(contains(s.bodies[0].shape, {0.75, 0.005, 0.005}));
}

TEST(SceneLoader, Tnt_slab_is_thesis_V2) {
  const Scene s = load_scene(kConfigs / "tnt_slab_1d.yaml");
  EXPECT_EQ(s.domain.cells[0], 1000);
  EXPECT_EQ(s.domain.upper[0] - s.domain.lower[0], 0.1);
  ASSERT_EQ(s.charges.size(), 1u);
  EXPECT_EQ(s.charges[0].detonation_point->at(0), 0.0);
  const Material* tnt = find_material(s, s.charges[0].material);
  ASSERT_NE(tnt, nullptr);
  EXPECT_EQ(tnt->explosive->detonation_velocity, 6930);
  EXPECT_EQ(std::get<eos::Jwl>(tnt->eos).rho0, 1630);
}

TEST(SceneLoader, Demo_scene_has_three_gauges_in_air) {
  const Scene s = load_scene(kConfigs / "demo.yaml");
  EXPECT_EQ(s.gauges.size(), 3u);
  EXPECT_EQ(s.domain.cells[0], 200);
}

// MPFD_WRITE_REFERENCE=1 rewrites configs/SCENE-REFERENCE.md instead of comparing.
TEST(SceneLoader, Checked_in_reference_is_the_schema_output) {
  const fs::path file = kConfigs / "SCENE-REFERENCE.md";
  if (const char* write = std::getenv("MPFD_WRITE_REFERENCE"); write && std::string(write) == "1") {
    std::ofstream(file) << print_schema();
  }
  EXPECT_EQ(read(file), print_schema())
      << "configs/SCENE-REFERENCE.md is stale; rerun this test with MPFD_WRITE_REFERENCE=1";
}

}  // namespace
}  // namespace mpfd::config::test
