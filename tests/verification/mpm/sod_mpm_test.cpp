// V1 of METHOD.md in MPM: Sod's shock tube (configs/sod_mpm.yaml) against the
// exact Riemann solution, trilinear MPM and GIMP at N = 100 ... 800 cells with
// 2 particles per cell and Courant number 0.1. The error is the particle L1
// norm, the volume-weighted mean of |f_p - f_exact(x_p)| over the particles,
// which is what a cell L1 becomes when the particles are the unknowns. The
// thesis (T §4.4.1) only says FDM converges ~50 % faster than GIMP.
// Measured (docs/mpm.md): GIMP converges slowly (order ~0.35 in rho, 0.5 in
// u); trilinear MPM does not converge in L1 here: its cell-crossing noise
// grows with the number of steps, so only its coarse error is checked.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/verification/support/convergence.hpp"
#include "tests/verification/support/exact_riemann.hpp"

namespace mpfd::mpm {
namespace {

struct SodErrors {
  double density, velocity, pressure, energy_drift;
};

SodErrors sod_errors(int cells, config::ShapeFunction shape) {
  auto scene = config::load_scene(std::string(MPFD_SOURCE_DIR) + "/configs/sod_mpm.yaml");
  scene.domain.cells[0] = cells;
  scene.solver.mpm.shape_function = shape;
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  const MpmTotals before = solver.totals();
  constexpr double kEnd = 0.2;
  solver.advance_to(kEnd);
  const MpmTotals after = solver.totals();
  const verification::ExactRiemann exact({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  const auto& ps = solver.particles();
  SodErrors e{0.0, 0.0, 0.0, 0.0};
  double volume = 0.0;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double v = ps.mass[p] / ps.density[p];
    const auto s = exact.sample((ps.position[0][p] - 0.5) / kEnd);
    e.density += std::abs(ps.density[p] - s.density) * v;
    e.velocity += std::abs(ps.velocity[0][p] - s.velocity) * v;
    e.pressure += std::abs(ps.pressure[p] - s.pressure) * v;
    volume += v;
  }
  e.density /= volume;
  e.velocity /= volume;
  e.pressure /= volume;
  const double e0 = before.kinetic_energy + before.internal_energy;
  e.energy_drift = (after.kinetic_energy + after.internal_energy - e0) / e0;
  return e;
}

void check_convergence(config::ShapeFunction shape, const std::vector<int>& resolutions,
                       double min_order, double max_energy_drift) {
  verification::ConvergenceStudy rho, vel, p;
  std::printf("%s\n%8s %12s %12s %12s %12s\n", shape_function_name(shape), "N", "L1(rho)", "L1(u)",
              "L1(p)", "dE/E");
  for (const int n : resolutions) {
    const SodErrors e = sod_errors(n, shape);
    std::printf("%8d %12.4e %12.4e %12.4e %12.3e\n", n, e.density, e.velocity, e.pressure,
                e.energy_drift);
    rho.add(n, e.density);
    vel.add(n, e.velocity);
    p.add(n, e.pressure);
    EXPECT_LT(std::abs(e.energy_drift), max_energy_drift) << "N = " << n;
  }
  std::printf("fitted order: rho %.3f, u %.3f, p %.3f\n", rho.fitted_order(), vel.fitted_order(),
              p.fitted_order());
  if (min_order > 0.0) {
    EXPECT_GT(rho.fitted_order(), min_order);
    EXPECT_GT(vel.fitted_order(), min_order);
    EXPECT_GT(p.fitted_order(), min_order);
  }
}

TEST(SodMpmFast, LinearAndGimpAt100CellsAreWithinAFewPercent) {
  const SodErrors linear = sod_errors(100, config::ShapeFunction::linear);
  const SodErrors gimp = sod_errors(100, config::ShapeFunction::gimp);
  EXPECT_LT(linear.density, 3.0e-2);
  EXPECT_LT(gimp.density, 2.0e-2);
  EXPECT_GT(gimp.density, 2.0e-3);  // a much smaller error would mean a broken reference
}

TEST(SodMpmFast, GimpConvergesInL1From100To800Cells) {
  check_convergence(config::ShapeFunction::gimp, {100, 200, 400, 800}, 0.3, 5e-3);
}

TEST(SodMpmFast, CpGimpConvergesInL1From100To800Cells) {
  check_convergence(config::ShapeFunction::cpgimp, {100, 200, 400, 800}, 0.6, 5e-4);
}

TEST(SodMpmFast, GimpIsMoreAccurateThanTrilinearAt400Cells) {
  const SodErrors linear = sod_errors(400, config::ShapeFunction::linear);
  const SodErrors gimp = sod_errors(400, config::ShapeFunction::gimp);
  EXPECT_LT(gimp.density, 0.5 * linear.density);
  EXPECT_LT(gimp.pressure, 0.5 * linear.pressure);
}

TEST(SodMpmFull, TrilinearTableFrom100To800Cells) {
  check_convergence(config::ShapeFunction::linear, {100, 200, 400, 800}, 0.0, 5e-2);
}

}  // namespace
}  // namespace mpfd::mpm
