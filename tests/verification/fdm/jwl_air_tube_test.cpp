// configs/jwl_air_tube.yaml: TNT products at the CJ state (20.98 GPa) against
// air at rest, a pressure ratio of 2e5, with massless tracers keeping the two
// materials apart. Compared at 40 us with a converged reference computed once
// (tests/verification/reference/make_jwl_air_tube_reference.sh: 8000 cells
// averaged onto 1000). Checks: relative L1 errors of density and pressure;
// first-order convergence; and the pressure at the material interface.
//
// Known limitation, bounded here: the single-velocity conservative update
// mixes the two materials' energies at the contact, which an EOS of either
// material then reads wrongly (Abgrall's EOS-mismatch error). It shows as a
// pressure dip of 13-27 % confined to 2-4 cells at the contact, of the
// same size at 500-8000 cells (so L1 still converges). The bounds below hold
// that dip: no deeper than 30 %, no wider than 4 cells.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/primitive_fields.hpp"

namespace mpfd::fdm {
namespace {

struct Profile {
  std::vector<double> x, density, velocity, pressure;
};

Profile reference() {
  std::ifstream in(MPFD_SOURCE_DIR "/tests/verification/reference/jwl_air_tube_40us.csv");
  Profile r;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line[0] == 'x') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    double x, rho, u, p;
    row >> x >> rho >> u >> p;
    r.x.push_back(x), r.density.push_back(rho), r.velocity.push_back(u), r.pressure.push_back(p);
  }
  return r;
}

/// Linear interpolation of a reference profile.
double at(const std::vector<double>& xs, const std::vector<double>& ys, double x) {
  const auto hi = std::upper_bound(xs.begin(), xs.end(), x);
  if (hi == xs.begin()) return ys.front();
  if (hi == xs.end()) return ys.back();
  const std::size_t k = static_cast<std::size_t>(hi - xs.begin());
  const double w = (x - xs[k - 1]) / (xs[k] - xs[k - 1]);
  return ys[k - 1] + w * (ys[k] - ys[k - 1]);
}

struct TubeResult {
  double l1_density, l1_pressure;
  double interface_dip;  ///< min over +-3 cells of p / (line between +-5 cells) - 1
  int interface_width;   ///< cells in that window more than 5 % off the line
  double mass_error, energy_error;
};

TubeResult run_tube(int cells) {
  auto scene = config::load_scene(MPFD_SOURCE_DIR "/configs/jwl_air_tube.yaml");
  scene.domain.cells = {cells, 1, 1};
  EulerSolver solver(scene, SolverOptions::from_scene(scene));
  const Totals start = solver.totals();
  const double end = scene.time.end;
  solver.advance_to(end);
  PrimitiveFields p;
  p.compute(solver.state(), solver.materials());
  const auto& rho = solver.state().u[kDensity];
  const Profile ref = reference();
  const double dx = 0.5 / cells;
  double err_rho = 0, err_p = 0, norm_rho = 0, norm_p = 0;
  for (int i = 0; i < cells; ++i) {
    const double x = (i + 0.5) * dx;
    const auto k = static_cast<std::size_t>(i);
    err_rho += std::abs(rho[k] - at(ref.x, ref.density, x));
    norm_rho += at(ref.x, ref.density, x);
    err_p += std::abs(p.pressure[k] - at(ref.x, ref.pressure, x));
    norm_p += at(ref.x, ref.pressure, x);
  }
  // The contact: the first air cell (material 0) from the products' side.
  int contact = 0;
  while (p.material[static_cast<std::size_t>(contact)] != 0.0) ++contact;
  const auto pa = p.pressure[static_cast<std::size_t>(contact - 5)];
  const auto pb = p.pressure[static_cast<std::size_t>(contact + 5)];
  double dip = 0.0;
  int width = 0;
  for (int i = contact - 3; i <= contact + 3; ++i) {
    const double line = pa + (pb - pa) * (i - contact + 5) / 10.0;
    const double off = p.pressure[static_cast<std::size_t>(i)] / line - 1.0;
    dip = std::min(dip, off);
    width += std::abs(off) > 0.05;
  }
  const Totals now = solver.totals();
  const auto& out = solver.outflow();
  return {err_rho / norm_rho,
          err_p / norm_p,
          dip,
          width,
          (now[kDensity] + out[kDensity]) / start[kDensity] - 1.0,
          (now[kEnergy] + out[kEnergy]) / start[kEnergy] - 1.0};
}

void report(int cells, const TubeResult& r) {
  std::printf(
      "%5d cells: L1 rho %.4f, L1 p %.4f, interface dip %.3f over %d cells, "
      "mass %.1e, energy %.1e\n",
      cells, r.l1_density, r.l1_pressure, r.interface_dip, r.interface_width, r.mass_error,
      r.energy_error);
}

TEST(JwlAirTubeFast, MatchesTheReferenceAndConvergesWithABoundedInterfaceDip) {
  const TubeResult coarse = run_tube(500);
  const TubeResult fine = run_tube(1000);
  report(500, coarse);
  report(1000, fine);
  EXPECT_LT(coarse.l1_density, 0.03);                   // measured 0.018
  EXPECT_LT(coarse.l1_pressure, 0.03);                  // measured 0.022
  EXPECT_GT(coarse.l1_density / fine.l1_density, 1.5);  // first order: ~2
  EXPECT_GT(coarse.l1_pressure / fine.l1_pressure, 1.5);
  for (const auto* r : {&coarse, &fine}) {
    EXPECT_GT(r->interface_dip, -0.30);
    EXPECT_LE(r->interface_width, 4);           // measured 4 at 500 cells, 2 at 1000
    EXPECT_LT(std::abs(r->mass_error), 1e-13);  // the positivity fallback stays conservative
    EXPECT_LT(std::abs(r->energy_error), 1e-13);
  }
}

}  // namespace
}  // namespace mpfd::fdm
