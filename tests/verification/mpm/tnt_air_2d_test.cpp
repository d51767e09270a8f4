// A 2D TNT charge in air in pure MPM (configs/tnt_air_2d_mpm.yaml, thesis V3
// geometry, coarse): the baseline the coupled methods must beat. Gauges on the
// x axis read the particle nearest to them every step. Checked: mass is
// conserved with what left through the outflow faces, the blast reaches the
// gauges in order of distance, and its peak overpressure falls with distance.
// The peaks and the wall time are printed (docs/mpm.md).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

constexpr double kAirPressure = 0.4 * 1.225 * 2.0685e5;  // gamma - 1 = 0.4 [Pa]

struct Gauge {
  double x = 0.0, y = 0.0;
  double peak = 0.0;          ///< largest overpressure [Pa]
  double arrival = -1.0;      ///< first time the overpressure exceeds 10 kPa [s]
  std::size_t peak_body = 0;  ///< body of the particle that read the peak
};

std::size_t nearest(const ParticleSet& ps, double x, double y) {
  std::size_t best = 0;
  double best_d2 = 1e300;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double dx = ps.position[0][p] - x, dy = ps.position[1][p] - y;
    if (dx * dx + dy * dy < best_d2) {
      best_d2 = dx * dx + dy * dy;
      best = p;
    }
  }
  return best;
}

/// Runs the scene with `coarsening` times fewer cells per active axis, to `end`.
std::vector<Gauge> run_charge(int coarsening, double end) {
  auto scene = config::load_scene(std::string(MPFD_SOURCE_DIR) + "/configs/tnt_air_2d_mpm.yaml");
  for (int a = 0; a < 2; ++a) scene.domain.cells[a] /= coarsening;
  scene.time.end = end;
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  const double mass0 = solver.totals().mass;
  std::vector<Gauge> gauges;
  for (const auto& g : scene.gauges) gauges.push_back({g.position[0], g.position[1]});
  const auto start = std::chrono::steady_clock::now();
  while (solver.time() < end) {
    solver.advance(solver.step_toward(end));
    const auto& ps = solver.particles();
    for (auto& g : gauges) {
      const std::size_t p = nearest(ps, g.x, g.y);
      const double over = ps.pressure[p] - kAirPressure;
      if (over > g.peak) {
        g.peak = over;
        g.peak_body = ps.body[p];
      }
      if (g.arrival < 0.0 && over > 1e4) g.arrival = solver.time();
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("h = %.1f mm, %zu particles, %lld steps, %.1f s wall\n",
              1e3 * (scene.domain.upper[0] - scene.domain.lower[0]) / scene.domain.cells[0],
              solver.particles().size(), static_cast<long long>(solver.steps()), seconds);
  for (const auto& g : gauges)
    std::printf(
        "  gauge r = %.2f m: arrival %.1f us, peak overpressure %.3f MPa (a particle of %s)\n", g.x,
        g.arrival * 1e6, g.peak / 1e6, solver.bodies()[g.peak_body].name.c_str());
  const double mass = solver.totals().mass + solver.boundary_ledger().mass;
  EXPECT_NEAR(mass, mass0, 1e-12 * mass0);
  for (std::size_t i = 0; i < gauges.size(); ++i) {
    EXPECT_GT(gauges[i].arrival, 0.0) << "gauge " << i << " saw no blast";
    if (i == 0) continue;
    EXPECT_GT(gauges[i].arrival, gauges[i - 1].arrival);
    EXPECT_LT(gauges[i].peak, gauges[i - 1].peak);
  }
  return gauges;
}

TEST(TntAir2dFast, CoarseBlastReachesTheGaugesInOrderAndWeakensWithDistance) {
  run_charge(2, 2.0e-4);  // h = 10 mm
}

TEST(TntAir2dFull, BlastPeaksAtTheGauges) {
  run_charge(1, 3.0e-4);
}  // h = 2.5 mm

}  // namespace
}  // namespace mpfd::mpm
