// The coupled step's cap from the strip cells (coupler/run/strip_step_limit.hpp).
#include "coupler/run/strip_step_limit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "tests/unit/coupler/run/air_tnt_steel_scene.hpp"

namespace mpfd::coupler {
namespace {

// The fluids a strip cell can hold: air (material 0) and TNT products (1).
using testing::kAirTntSteelScene;

using Vec2 = handshake::Vec<2>;

struct Cells {
  std::vector<double> rho, energy, pressure;
  std::vector<Vec2> momentum;

  /// Appends a cell of density d, velocity u and specific internal energy e of `eos`.
  void add(const eos::AnyEos& eos, double d, const Vec2& u, double e) {
    rho.push_back(d);
    momentum.push_back(d * u);
    energy.push_back(d * (e + 0.5 * u.squaredNorm()));
    pressure.push_back(eos::pressure(eos, d, e));
  }
  [[nodiscard]] double limit(const config::Scene& scene, double cfl, double h) const {
    const InjectedMaterial materials(scene);
    return strip_step_limit<2>(rho, momentum, energy, pressure, materials, scene, cfl, h);
  }
};

TEST(StripStepLimit, AirAtRestGivesTheMpmCourantStepOfItsSoundSpeed) {
  const auto scene = config::parse_scene(kAirTntSteelScene, "strip.yaml");
  const auto& air = scene.materials[0].eos;
  Cells cells;
  for (int c = 0; c < 4; ++c) cells.add(air, 1.225, Vec2::Zero(), 2.0685e5);
  const double sound = std::sqrt(1.4 * 0.4 * 2.0685e5);  // c^2 = gamma (gamma - 1) e
  EXPECT_NEAR(cells.limit(scene, 0.25, 2.0e-3), 0.25 * 2.0e-3 / sound, 1e-12 * 2.0e-3 / sound);
}

TEST(StripStepLimit, TheFastestCellSetsTheStep) {
  const auto scene = config::parse_scene(kAirTntSteelScene, "strip.yaml");
  const auto& air = scene.materials[0].eos;
  Cells cells;
  cells.add(air, 1.225, Vec2::Zero(), 2.0685e5);
  // Shocked air behind a 1 MPa blast front: rho 5.3, u 700 m/s, e 4.8e5 J/kg.
  cells.add(air, 5.3, Vec2(600.0, -360.555), 4.8e5);
  cells.add(air, 1.225, Vec2::Zero(), 2.0685e5);
  const double fastest = std::sqrt(1.4 * 0.4 * 4.8e5) + std::hypot(600.0, -360.555);
  EXPECT_NEAR(cells.limit(scene, 0.3, 1.0e-3), 0.3 * 1.0e-3 / fastest, 1e-9 * 1.0e-3 / fastest);
}

TEST(StripStepLimit, ProductsTakeTheSoundSpeedOfTheirOwnEos) {
  const auto scene = config::parse_scene(kAirTntSteelScene, "strip.yaml");
  const auto& jwl = scene.materials[1].eos;
  Cells cells;
  cells.add(jwl, 100.0, Vec2(2000.0, 0.0), 3.0e6);  // expanded products
  const double fastest = eos::sound_speed(jwl, 100.0, 3.0e6) + 2000.0;
  // The ideal gas at this state would give a different (faster) speed: the EOS matters.
  ASSERT_GT(std::abs(eos::sound_speed(scene.materials[0].eos, 100.0, 3.0e6) -
                     eos::sound_speed(jwl, 100.0, 3.0e6)),
            10.0);
  EXPECT_NEAR(cells.limit(scene, 0.25, 1.0e-3), 0.25 * 1.0e-3 / fastest, 1e-12 * 1.0e-3 / fastest);
}

TEST(StripStepLimit, EmptyCellsDoNotCount) {
  const auto scene = config::parse_scene(kAirTntSteelScene, "strip.yaml");
  Cells cells;
  cells.rho = {0.0, 0.0};
  cells.energy = {0.0, 0.0};
  cells.pressure = {0.0, 0.0};
  cells.momentum = {Vec2::Zero(), Vec2::Zero()};
  EXPECT_EQ(cells.limit(scene, 0.25, 1.0e-3), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace mpfd::coupler
