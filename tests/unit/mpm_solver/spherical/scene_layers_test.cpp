// The scene route into the 1D spherical MPM (design §2.3): configs/underwater_1d.yaml
// gives underwater_case.hpp's layers and options bit for bit, regions become
// layers in the scene's overwrite order, the AFDMP 1D start takes its own
// options, and `mpm_solver run`'s spherical run records the same pressures as
// a direct run of the test case, step by step.
#include "mpm_solver/spherical/scene_layers.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <variant>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "common/io/hdf5_file.hpp"
#include "mpm_solver/spherical/spherical_run.hpp"
#include "underwater_case.hpp"

namespace mpfd::mpm::spherical {
namespace {

namespace fs = std::filesystem;

const fs::path kScene = fs::path(MPFD_SOURCE_DIR) / "configs" / "underwater_1d.yaml";

void expect_same_layer(const RadialLayer& got, const RadialLayer& want) {
  EXPECT_EQ(got.outer_radius, want.outer_radius);
  EXPECT_EQ(got.density, want.density);
  EXPECT_EQ(got.specific_internal_energy, want.specific_internal_energy);
  EXPECT_EQ(got.explosive, want.explosive);
  EXPECT_EQ(got.material.eos.index(), want.material.eos.index());
  EXPECT_EQ(got.material.explosive.has_value(), want.material.explosive.has_value());
  EXPECT_TRUE(std::holds_alternative<config::NoStrength>(got.material.strength));
}

TEST(SceneLayers, UnderwaterSceneGivesTheTestCaseLayers) {
  const config::Scene scene = config::load_scene(kScene);
  const std::vector<RadialLayer> got = layers_from_scene(scene);
  const std::vector<RadialLayer> want = testing::underwater_layers(5.0);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) expect_same_layer(got[i], want[i]);
  const auto& jwl = std::get<eos::Jwl>(got[0].material.eos);
  const auto& jwl_case = std::get<eos::Jwl>(want[0].material.eos);
  EXPECT_EQ(jwl.a, jwl_case.a);
  EXPECT_EQ(jwl.b, jwl_case.b);
  EXPECT_EQ(jwl.detonation_energy, jwl_case.detonation_energy);
  EXPECT_EQ(got[0].material.explosive->detonation_velocity,
            want[0].material.explosive->detonation_velocity);
  const auto& water = std::get<eos::Polynomial>(got[1].material.eos);
  const auto& water_case = std::get<eos::Polynomial>(want[1].material.eos);
  EXPECT_EQ(water.a1, water_case.a1);
  EXPECT_EQ(water.a2, water_case.a2);
  EXPECT_EQ(water.a3, water_case.a3);
  EXPECT_EQ(water.b0, water_case.b0);
  EXPECT_EQ(water.b1, water_case.b1);
  EXPECT_EQ(water.t1, water_case.t1);
  EXPECT_EQ(water.t2, water_case.t2);

  const SphericalOptions o = options_from_scene(scene);
  EXPECT_EQ(o.grid_spacing, 0.01);  // S: h = 10 mm
  EXPECT_EQ(o.particles_per_cell, 2);
  EXPECT_EQ(o.cfl, 0.5);
  EXPECT_EQ(o.shape, RadialShape::gimp);
  EXPECT_EQ(o.outer_boundary, OuterBoundary::transmitting);
  EXPECT_EQ(o.viscosity.quadratic, BulkViscosity{}.quadratic);
  EXPECT_EQ(o.viscosity.linear, BulkViscosity{}.linear);
}

const std::string kShells = R"(name: shells
time: {end: 1.0e-4}
domain: {lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [100, 1, 1], geometry: spherical}
materials:
  tnt:
    eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
  air: {eos: {type: ideal_gas, gamma: 1.4}}
initial: {material: air, density: 1.225, pressure: 1.0e5}
bodies:
  - {name: big, material: air, density: 2.0, pressure: 2.0e5, shape: {sphere: {center: [0, 0, 0], radius: 0.5}}}
  - {name: small, material: air, density: 3.0, pressure: 3.0e5, shape: {sphere: {center: [0, 0, 0], radius: 0.2}}}
  - {name: hidden, material: air, density: 4.0, pressure: 4.0e5, shape: {sphere: {center: [0, 0, 0], radius: 0.1}}}
charges:
  - {name: core, material: tnt, shape: {sphere: {center: [0, 0, 0], radius: 0.15}}, detonation_point: [0, 0, 0]}
boundaries: {x_lower: symmetry, x_upper: outflow}
output: {interval: 1.0e-5}
solver: {method: mpm, mpm: {shape_function: linear, bulk_viscosity_linear: 0.1}}
)";

TEST(SceneLayers, LaterRegionsOverwriteEarlierOnesAndEnergyComesFromPressure) {
  const config::Scene scene = config::parse_scene(kShells, "shells.yaml");
  const std::vector<RadialLayer> layers = layers_from_scene(scene);
  // core (0.15, over hidden), small to 0.2, big to 0.5, initial to 1.
  ASSERT_EQ(layers.size(), 4u);
  EXPECT_EQ(layers[0].outer_radius, 0.15);
  EXPECT_TRUE(layers[0].explosive);
  EXPECT_EQ(layers[0].density, 1630.0);
  EXPECT_EQ(layers[0].specific_internal_energy, 6.993e9 / 1630.0);
  EXPECT_EQ(layers[1].outer_radius, 0.2);
  EXPECT_EQ(layers[1].density, 3.0);
  EXPECT_EQ(layers[2].outer_radius, 0.5);
  EXPECT_EQ(layers[2].density, 2.0);
  EXPECT_EQ(layers[3].outer_radius, 1.0);
  EXPECT_EQ(layers[3].density, 1.225);
  // Ideal gas: e = p / ((gamma - 1) rho).
  EXPECT_NEAR(layers[3].specific_internal_energy, 1.0e5 / (0.4 * 1.225), 1e-9 * 2.0e5);
  EXPECT_NEAR(layers[1].specific_internal_energy, 3.0e5 / (0.4 * 3.0), 1e-9 * 2.5e5);
  const SphericalOptions o = options_from_scene(scene);
  EXPECT_EQ(o.shape, RadialShape::linear);
  EXPECT_EQ(o.outer_boundary, OuterBoundary::free);
  EXPECT_EQ(o.viscosity.linear, 0.1);
  EXPECT_EQ(o.grid_spacing, 0.01);
}

// The AFDMP 1D start in a 3D octant: the air body in `initial`'s state is the
// background, a box away from the line is left out, and the options are
// solver.afdmp.spherical's.
const std::string kOctant = R"(name: octant
time: {end: 1.0e-4}
domain: {lower: [0, 0, 0], upper: [0.25, 0.25, 0.25], cells: [100, 100, 100]}
materials:
  tnt:
    eos: {type: jwl, rho0: 1630, A: 371.2e9, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3, E0: 6.993e9}
    explosive: {detonation_velocity: 6930}
  air: {eos: {type: ideal_gas, gamma: 1.4}}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
bodies:
  - {name: air, material: air, density: 1.225, specific_internal_energy: 2.0685e5, particles_per_axis: 1,
     shape: {box: {lower: [0, 0, 0], upper: [0.25, 0.25, 0.25]}}}
  - {name: far, material: air, density: 5.0, specific_internal_energy: 2.0685e5,
     shape: {box: {lower: [0.2, 0.2, 0.2], upper: [0.25, 0.25, 0.25]}}}
charges:
  - {name: ball, material: tnt, shape: {sphere: {center: [0, 0, 0], radius: 0.0125}}, detonation_point: [0, 0, 0]}
boundaries: {x_lower: symmetry, y_lower: symmetry, z_lower: symmetry}
output: {interval: 1.0e-5}
solver:
  method: afdmp
  afdmp: {start: spherical, spherical: {handoff_radius: 0.04, cfl: 0.3}}
)";

TEST(SceneLayers, AfdmpStartTakesTheChargeInTheBackgroundAndItsOwnOptions) {
  const config::Scene scene = config::parse_scene(kOctant, "octant.yaml");
  const std::vector<RadialLayer> layers = layers_from_scene(scene, {0.0, 0.0, 0.0}, 0.05);
  ASSERT_EQ(layers.size(), 2u);
  EXPECT_EQ(layers[0].outer_radius, 0.0125);
  EXPECT_TRUE(layers[0].explosive);
  EXPECT_EQ(layers[1].outer_radius, 0.05);
  EXPECT_EQ(layers[1].density, 1.225);
  EXPECT_EQ(layers[1].specific_internal_energy, 2.0685e5);
  const SphericalOptions o = options_from_scene(scene);
  EXPECT_EQ(o.grid_spacing, 0.0025 / 4.0);  // the domain's h / 4
  EXPECT_EQ(o.cfl, 0.3);
  EXPECT_EQ(o.particles_per_cell, 2);
  EXPECT_EQ(o.shape, RadialShape::gimp);
  EXPECT_EQ(o.outer_boundary, OuterBoundary::transmitting);
  EXPECT_THROW((void)layers_from_scene(scene, {0.0, 0.0, 0.0}, 0.4), Error);  // reaches `far`
}

// underwater_1d.yaml at the fast test's h = 20 mm, water to 2.5 m.
config::Scene fast_underwater() {
  config::Scene s = config::load_scene(kScene);
  s.domain.upper[0] = 2.5;
  s.domain.cells[0] = 125;
  s.time.end = 2.0 / 1400.0;
  s.output.interval = s.time.end;
  s.gauges.erase(s.gauges.begin() + 6, s.gauges.end());  // R <= 2.5 m
  return s;
}

TEST(SceneLayers, MpmSolverRunRecordsTheTestCasePressuresBitForBit) {
  const config::Scene scene = fast_underwater();
  const fs::path out = fs::path(::testing::TempDir()) / "spherical_run_bitwise";
  run_spherical(scene, {kScene, out, true});

  SphericalOptions o;
  o.grid_spacing = 0.02;
  o.outer_boundary = OuterBoundary::transmitting;
  SphericalMpm mpm(testing::underwater_layers(2.5), o);
  std::vector<double> radii;
  for (const auto& g : scene.gauges) radii.push_back(g.position[0]);
  std::vector<double> times{mpm.time()};
  std::vector<std::vector<double>> pressures(radii.size());
  const auto sample = [&] {
    for (std::size_t g = 0; g < radii.size(); ++g)
      pressures[g].push_back(mpm.pressure_at(radii[g]));
  };
  sample();
  while (mpm.time() < scene.time.end) {
    mpm.advance(std::min(mpm.stable_dt(), scene.time.end - mpm.time()));
    times.push_back(mpm.time());
    sample();
  }

  const io::Hdf5File h5(out / "gauges.h5", io::Hdf5File::Mode::read);
  const io::DatasetData time = h5.read_dataset("/time");
  ASSERT_EQ(time.values.size(), times.size());
  EXPECT_GT(times.size(), 100u);
  for (std::size_t k = 0; k < times.size(); ++k) ASSERT_EQ(time.values[k], times[k]) << k;
  for (std::size_t g = 0; g < radii.size(); ++g) {
    const io::DatasetData p = h5.read_dataset("/gauges/" + scene.gauges[g].name + "/pressure");
    ASSERT_EQ(p.values.size(), pressures[g].size());
    for (std::size_t k = 0; k < p.values.size(); ++k)
      ASSERT_EQ(p.values[k], pressures[g][k]) << scene.gauges[g].name << " sample " << k;
  }
  EXPECT_TRUE(fs::exists(out / "profiles" / "profile_000000.csv"));
  EXPECT_TRUE(fs::exists(out / "profiles" / "profile_000001.csv"));
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

}  // namespace
}  // namespace mpfd::mpm::spherical
