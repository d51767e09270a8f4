// The material of particles made from FDM material (coupler/run/injected_material.hpp).
#include "coupler/run/injected_material.hpp"

#include <gtest/gtest.h>

#include "common/config/scene_loader.hpp"

namespace mpfd::coupler {
namespace {

// Air around TNT products (T Table 3.1) and a steel plate (elastic: not a fluid).
constexpr const char* kScene = R"(name: mix
time: {end: 1.0e-5}
domain: {lower: [0, 0, 0], upper: [1, 1, 0.01], cells: [10, 10, 1]}
materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
  tnt:
    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3,
          E0: 6.993e9}
  steel:
    eos: {type: ideal_gas, gamma: 3.0}
    strength: {type: elastic, shear_modulus: 8.0e10}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
bodies:
  - {name: products, material: tnt, density: 1630, specific_internal_energy: 4.2902e6,
     shape: {box: {lower: [0, 0, 0], upper: [0.2, 0.2, 0.01]}}}
  - {name: plate, material: steel, density: 7800, pressure: 1.0e5,
     shape: {box: {lower: [0.8, 0, 0], upper: [1, 1, 0.01]}}}
output: {interval: 1.0e-5}
)";

TEST(InjectedMaterial, The_fluid_whose_eos_matches_the_fdm_pressure_is_chosen) {
  const auto scene = config::parse_scene(kScene, "mix.yaml");
  const InjectedMaterial chooser(scene);
  // Products expanded to rho = 100 kg/m^3, e = 3e6 J/kg: JWL gives ~0.3 rho e
  // (plus its small exponential terms), air 0.4 rho e = 120 MPa.
  const double rho = 100, e = 3.0e6;
  const double p_jwl = eos::pressure(scene.materials[1].eos, rho, e);
  EXPECT_NEAR(p_jwl / (rho * e), 0.3, 0.01);
  EXPECT_EQ(chooser.choose(rho, e, p_jwl), 1u);
  EXPECT_EQ(chooser.choose(rho, e, 0.4 * rho * e), 0u);
  EXPECT_EQ(chooser.choose(1.225, 2.0685e5, 1.0136e5), 0u);
  // The steel plate has strength: never a candidate, even at its own pressure.
  EXPECT_NE(chooser.choose(7800, 100, eos::pressure(scene.materials[2].eos, 7800, 100)), 2u);
}

TEST(InjectedMaterial, One_fluid_is_always_chosen) {
  auto scene = config::parse_scene(kScene, "mix.yaml");
  scene.bodies.clear();
  const InjectedMaterial chooser(scene);
  EXPECT_EQ(chooser.choose(100, 3.0e6, 0.3 * 100 * 3.0e6), 0u);
}

}  // namespace
}  // namespace mpfd::coupler
