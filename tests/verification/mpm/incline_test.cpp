// A block sliding on an incline (T §2.1.3, the classic check of frictional
// contact): a 2D elastic block rests on a fixed elastic slab (a fixed particle
// set) and gravity is tilted by theta, so the slope is the grid's x axis and
// the block's acceleration along it must be g (sin theta - mu cos theta).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

constexpr double kG = 9.81;

std::string incline_scene(double theta, const std::string& contact) {
  char gravity[64];
  std::snprintf(gravity, sizeof gravity, "[%.17g, %.17g, 0]", kG * std::sin(theta),
                -kG * std::cos(theta));
  return R"(
name: incline
time: {end: 0.2, cfl: 0.5}
domain: {lower: [0, 0, 0], upper: [0.4, 0.1, 0.01], cells: [40, 10, 1]}
materials:
  rubber:
    eos: {type: polynomial, rho0: 1000, A1: 1.0e7, T1: 1.0e7}
    strength: {type: elastic, shear_modulus: 5.0e6}
initial: {material: rubber, density: 1000, specific_internal_energy: 0}
bodies:
  - {name: slope, material: rubber, density: 1000, specific_internal_energy: 0, fixed: true,
     shape: {box: {lower: [0, 0, 0], upper: [0.4, 0.03, 0.01]}}}
  - {name: block, material: rubber, density: 1000, specific_internal_energy: 0,
     shape: {box: {lower: [0.05, 0.03, 0], upper: [0.1, 0.06, 0.01]}}}
output: {interval: 1.0}
solver:
  method: mpm
  mpm: {gravity: )" +
         std::string(gravity) + ", " + contact + "}\n";
}

struct Slide {
  double acceleration;  ///< least-squares slope of the block's mean x velocity [m/s^2]
  double start_y;       ///< block's mean height at the start and the end [m]
  double end_y;
};

Slide slide(double theta, const std::string& contact) {
  const auto scene = config::parse_scene(incline_scene(theta, contact), "incline.yaml");
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  const auto mean = [&](int axis, const auto& field) {
    const auto& ps = solver.particles();
    double sum = 0.0, mass = 0.0;
    for (std::size_t p = 0; p < ps.size(); ++p) {
      if (ps.body[p] != 1) continue;
      sum += ps.mass[p] * field[static_cast<std::size_t>(axis)][p];
      mass += ps.mass[p];
    }
    return sum / mass;
  };
  const double start_y = mean(1, solver.particles().position);
  // Least squares of v(t) over [0.05, 0.2] s, after the block has settled on the slab.
  double st = 0, sv = 0, stt = 0, stv = 0, n = 0;
  for (int sample = 1; sample <= 30; ++sample) {
    solver.advance_to(0.05 + 0.15 * sample / 30.0);
    const double t = solver.time(), v = mean(0, solver.particles().velocity);
    st += t, sv += v, stt += t * t, stv += t * v, n += 1;
  }
  return {(n * stv - st * sv) / (n * stt - st * st), start_y, mean(1, solver.particles().position)};
}

TEST(InclineFast, BlockSlidesAtGTimesSinMinusMuCos) {
  const double theta = std::numbers::pi / 6;
  for (const double mu : {0.0, 0.2}) {
    char contact[64];
    std::snprintf(contact, sizeof contact, "contact: {friction: %.17g}", mu);
    const Slide run = slide(theta, contact);
    const double expected = kG * (std::sin(theta) - mu * std::cos(theta));
    std::printf("mu = %.1f: a = %.4f m/s^2, expected %.4f (%+.2f %%); height %.5f -> %.5f m\n", mu,
                run.acceleration, expected, 100 * (run.acceleration / expected - 1), run.start_y,
                run.end_y);
    EXPECT_NEAR(run.acceleration, expected, 0.005 * expected);
    EXPECT_NEAR(run.end_y, run.start_y, 1e-4);  // a hundredth of a cell: no sinking, no lift-off
  }
  // Without contact (one velocity field) the fixed slab holds the block: no slip.
  const Slide stuck = slide(theta, "shear_damping: 0");
  std::printf("no contact: a = %.3e m/s^2\n", stuck.acceleration);
  EXPECT_LT(std::abs(stuck.acceleration), 0.05 * kG * std::sin(theta));
}

}  // namespace
}  // namespace mpfd::mpm
