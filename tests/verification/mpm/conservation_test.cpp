// Conservation and rest checks of the MPM step (METHOD.md §1, T Fig. 2.4):
// * air at rest in a closed box (configs/quiet_air_box.yaml) stays at rest and
//   uniform for 10 ms;
// * two gas bodies in free flight collide: mass is exact and momentum is
//   conserved to round-off (the internal forces of MPM sum to zero at the
//   nodes; no face is touched).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

TEST(QuietAirBoxFast, AirAtRestInAClosedBoxStaysAtRestFor10ms) {
  for (const auto shape : {config::ShapeFunction::linear, config::ShapeFunction::gimp,
                           config::ShapeFunction::cpgimp}) {
    auto scene = config::load_scene(std::string(MPFD_SOURCE_DIR) + "/configs/quiet_air_box.yaml");
    scene.solver.mpm.shape_function = shape;
    MpmSolver solver(scene, MpmSettings::from_scene(scene));
    const double p0 = solver.particles().pressure[0];
    solver.advance_to(scene.time.end);
    const auto& ps = solver.particles();
    double speed = 0.0, dp = 0.0;
    for (std::size_t p = 0; p < ps.size(); ++p) {
      speed = std::max(speed, std::abs(ps.velocity[0][p]));
      dp = std::max(dp, std::abs(ps.pressure[p] - p0));
    }
    std::printf("%s: %lld steps, max |v| = %.3e m/s, max |p - p0| / p0 = %.3e\n",
                shape_function_name(shape), static_cast<long long>(solver.steps()), speed, dp / p0);
    EXPECT_LT(speed, 1e-9);  // c = 340 m/s
    EXPECT_LT(dp / p0, 1e-12);
  }
}

TEST(FreeFlightFast, TwoGasBodiesCollideWithExactMassAndMomentumToRoundOff) {
  const std::string text = R"(
name: collision
time: {end: 3.0e-4}
domain: {lower: [-0.5, -0.5, 0], upper: [1.5, 1.5, 0.01], cells: [200, 200, 1]}
materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
  gas: {eos: {type: ideal_gas, gamma: 1.67}}
initial: {material: air, density: 1, pressure: 1.0e5}
bodies:
  - {name: a, material: air, density: 1.2, pressure: 1.0e5, velocity: [400, 100, 0],
     shape: {box: {lower: [0.2, 0.3, 0], upper: [0.45, 0.6, 0.01]}}}
  - {name: b, material: gas, density: 5.0, pressure: 3.0e5, velocity: [-200, 0, 0],
     shape: {sphere: {center: [0.62, 0.5, 0.005], radius: 0.12}}}
output: {interval: 1.0}
solver: {method: mpm}
)";
  for (const auto shape : {config::ShapeFunction::linear, config::ShapeFunction::gimp,
                           config::ShapeFunction::cpgimp}) {
    auto scene = config::parse_scene(text, "collision.yaml");
    scene.solver.mpm.shape_function = shape;
    MpmSolver solver(scene, MpmSettings::from_scene(scene));
    const MpmTotals before = solver.totals();
    solver.advance_to(scene.time.end);
    const MpmTotals after = solver.totals();
    ASSERT_EQ(solver.boundary_ledger().particles_removed, 0);
    const double scale = std::hypot(before.momentum[0], before.momentum[1]);
    const double dpx = (after.momentum[0] - before.momentum[0]) / scale;
    const double dpy = (after.momentum[1] - before.momentum[1]) / scale;
    const double e0 = before.kinetic_energy + before.internal_energy;
    const double de = (after.kinetic_energy + after.internal_energy - e0) / e0;
    std::printf("%s: %lld steps, dm/m = %.2e, dp/|p| = (%.2e, %.2e), dE/E = %.2e\n",
                shape_function_name(shape), static_cast<long long>(solver.steps()),
                (after.mass - before.mass) / before.mass, dpx, dpy, de);
    EXPECT_EQ(after.mass, before.mass);
    EXPECT_LT(std::abs(dpx), 1e-12);  // 148 steps of round-off: measured 2e-13
    EXPECT_LT(std::abs(dpy), 1e-12);
    EXPECT_GT(solver.steps(), 100);
  }
}

}  // namespace
}  // namespace mpfd::mpm
