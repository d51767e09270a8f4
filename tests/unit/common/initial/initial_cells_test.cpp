#include "common/initial/initial_cells.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/core/error.hpp"

namespace mpfd::initial {
namespace {

using ::testing::HasSubstr;

const eos::Jwl kTnt{1630.0, 371.2e9, 3.21e9, 4.15, 0.95, 0.3, 6.993e9};  // T Table 3.1

/// A 1D tube of 10 cells over 1 m: air at 1e5 Pa, a dense box on [0.2, 0.5)
/// given by its pressure, and a TNT slab on [0, 0.2).
config::Scene tube(config::Burn burn) {
  config::Scene s;
  s.name = "tube";
  s.domain = {{0, 0, 0}, {1, 0.1, 0.1}, {10, 1, 1}};
  s.materials = {{"air", eos::IdealGas{1.4}, config::NoStrength{}, std::nullopt},
                 {"tnt", kTnt, config::NoStrength{}, config::Explosive{6930.0}}};
  s.initial = {"air", 1.225, {0, 0, 0}, std::nullopt, 2.0685e5};
  s.bodies = {{"dense",
               {config::Box{{0.2, 0, 0}, {0.5, 0.1, 0.1}}},
               {"air", 12.25, {50.0, 0, 0}, 1.0e6, std::nullopt},
               2}};
  s.charges = {{"slab",
                "tnt",
                {config::Box{{0, 0, 0}, {0.2, 0.1, 0.1}}},
                grid::Vec3{0, 0.05, 0.05},
                burn,
                2}};
  return s;
}

TEST(InitialCells, LaterShapesOverwriteEarlierOnesAtCellCentres) {
  const auto scene = tube(config::Burn::program);
  const auto grid = scene_grid(scene);
  const auto f = initial_cells(scene, grid);
  EXPECT_EQ(f.material[1], 1.0);  // centre 0.15: charge
  EXPECT_EQ(f.material[2], 0.0);  // centre 0.25: body
  EXPECT_DOUBLE_EQ(f.density[4], 12.25);
  EXPECT_DOUBLE_EQ(f.velocity_x[4], 50.0);
  EXPECT_DOUBLE_EQ(f.density[5], 1.225);  // centre 0.55: background
  EXPECT_DOUBLE_EQ(f.velocity_x[5], 0.0);
}

TEST(InitialCells, AStateGivenByPressureGetsTheEnergyItsEosNeeds) {
  const auto scene = tube(config::Burn::program);
  const auto f = initial_cells(scene, scene_grid(scene));
  EXPECT_NEAR(f.pressure[3], 1.0e6, 1e-6);
  EXPECT_NEAR(f.specific_internal_energy[3], 1.0e6 / (0.4 * 12.25), 1e-6);  // T (2-59)
  EXPECT_NEAR(f.pressure[7], 0.4 * 1.225 * 2.0685e5, 1e-6);
  EXPECT_NEAR(f.sound_speed[7], std::sqrt(1.4 * f.pressure[7] / 1.225), 1e-9);
}

TEST(InitialCells, ProgramBurnChargeStartsUnlitInstantaneousBurnAtFullJwlPressure) {
  const double e0 = kTnt.detonation_energy / kTnt.rho0;
  const auto unlit = tube(config::Burn::program);
  const auto f0 = initial_cells(unlit, scene_grid(unlit));
  EXPECT_DOUBLE_EQ(f0.density[0], 1630.0);
  EXPECT_DOUBLE_EQ(f0.specific_internal_energy[0], e0);
  EXPECT_EQ(f0.pressure[0], 0.0);  // F = 0 before the front, T (3-2)
  EXPECT_EQ(f0.burn_fraction[0], 0.0);

  const auto lit = tube(config::Burn::instantaneous);
  const auto f1 = initial_cells(lit, scene_grid(lit));
  EXPECT_DOUBLE_EQ(f1.pressure[0], kTnt.pressure(1630.0, e0));
  // The constant-volume explosion state of TNT is ~ 9.5 GPa (about half p_CJ).
  EXPECT_GT(f1.pressure[0], 8e9);
  EXPECT_LT(f1.pressure[0], 11e9);
}

TEST(InitialCells, NonPositiveDensityIsRefusedNamingTheBody) {
  auto scene = tube(config::Burn::program);
  scene.bodies[0].state.density = 0.0;
  try {
    (void)initial_cells(scene, scene_grid(scene));
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("body 'dense'"));
    EXPECT_THAT(e.what(), HasSubstr("density must be > 0"));
  }
}

}  // namespace
}  // namespace mpfd::initial
