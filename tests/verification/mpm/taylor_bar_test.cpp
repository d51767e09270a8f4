// Taylor bar (configs/taylor_bar.yaml): the copper bar of Wilkins & Guinan
// (1973) as computed by Simo (1992, §7.2): 32.4 mm x 3.2 mm radius, 227 m/s
// onto a rigid frictionless wall, J2 plasticity with linear hardening, one
// quarter in 3D. Published at 80 us: radius of the impact face 7.12 mm (Simo),
// 7.11 mm (Zienkiewicz et al. 1998), 7.22 mm (converged hexahedra, Foulk et
// al. 2021); length 21.42-21.48 mm (the same finite-element runs).
// The surface is estimated from the particles: the largest particle radius
// (or height) plus half the initial particle spacing. cpGIMP, frictionless
// wall (configs/taylor_bar.yaml says why). References used: length 21.45 mm,
// radius 7.16 mm (the middle of 7.11-7.22).

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

struct TaylorResult {
  double length = 0.0;       ///< [m]
  double foot_radius = 0.0;  ///< [m]
  double kinetic_fraction = 0.0;
  std::size_t particles = 0;
};

/// Runs the bar with `coarsening` times fewer cells per axis than the scene file.
TaylorResult run_taylor(int coarsening) {
  auto scene = config::load_scene(std::string(MPFD_SOURCE_DIR) + "/configs/taylor_bar.yaml");
  for (int a = 0; a < 3; ++a) scene.domain.cells[a] /= coarsening;
  const double h = (scene.domain.upper[0] - scene.domain.lower[0]) / scene.domain.cells[0];
  const double half_spacing = 0.25 * h;  // 2 particles per cell and axis
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  const double kinetic0 = solver.totals().kinetic_energy;
  const auto start = std::chrono::steady_clock::now();
  solver.advance_to(scene.time.end);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto& ps = solver.particles();
  TaylorResult r;
  r.particles = ps.size();
  for (std::size_t p = 0; p < ps.size(); ++p) {
    r.length = std::max(r.length, ps.position[2][p]);
    r.foot_radius = std::max(r.foot_radius, std::hypot(ps.position[0][p], ps.position[1][p]));
  }
  r.length += half_spacing;
  r.foot_radius += half_spacing;
  r.kinetic_fraction = solver.totals().kinetic_energy / kinetic0;
  std::printf(
      "h = %.2f mm, %zu particles, %lld steps, %.1f s: length %.3f mm, foot radius %.3f mm, "
      "kinetic energy left %.4f\n",
      h * 1e3, r.particles, static_cast<long long>(solver.steps()), seconds, r.length * 1e3,
      r.foot_radius * 1e3, r.kinetic_fraction);
  EXPECT_EQ(solver.boundary_ledger().particles_removed, 0);
  return r;
}

TEST(TaylorBarFast, CoarseBarEndsNearThePublishedShape) {
  const TaylorResult r = run_taylor(2);  // h = 0.8 mm
  EXPECT_NEAR(r.length, 21.45e-3, 0.03 * 21.45e-3);
  EXPECT_NEAR(r.foot_radius, 7.16e-3, 0.04 * 7.16e-3);
  EXPECT_LT(r.kinetic_fraction, 0.02);
}

TEST(TaylorBarFull, BarEndsAtThePublishedShape) {
  const TaylorResult r = run_taylor(1);  // h = 0.4 mm
  EXPECT_NEAR(r.length, 21.45e-3, 0.02 * 21.45e-3);
  EXPECT_NEAR(r.foot_radius, 7.16e-3, 0.03 * 7.16e-3);
  EXPECT_LT(r.kinetic_fraction, 0.02);
}

}  // namespace
}  // namespace mpfd::mpm
