// The material of particles made from FDM material (coupler/run/injected_material.hpp).
#include "coupler/run/injected_material.hpp"

#include <gtest/gtest.h>

#include "common/config/scene_loader.hpp"
#include "tests/unit/coupler/run/air_tnt_steel_scene.hpp"

namespace mpfd::coupler {
namespace {

using testing::kAirTntSteelScene;

TEST(InjectedMaterial, The_fluid_whose_eos_matches_the_fdm_pressure_is_chosen) {
  const auto scene = config::parse_scene(kAirTntSteelScene, "mix.yaml");
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
  auto scene = config::parse_scene(kAirTntSteelScene, "mix.yaml");
  scene.bodies.clear();
  const InjectedMaterial chooser(scene);
  EXPECT_EQ(chooser.choose(100, 3.0e6, 0.3 * 100 * 3.0e6), 0u);
}

}  // namespace
}  // namespace mpfd::coupler
