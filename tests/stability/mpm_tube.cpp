#include "tests/stability/mpm_tube.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "tests/stability/stability_cases.hpp"
#include "tests/verification/support/exact_riemann.hpp"

namespace mpfd::stability {

RiemannProblem hard_riemann_problem(std::string_view name) {
  for (RiemannProblem& p : hard_riemann_problems())
    if (p.name == name) return p;
  throw Error("no hard Riemann problem '" + std::string(name) + "'");
}

double audited_energy(const mpm::MpmSolver& mpm) {
  const auto t = mpm.totals();
  return t.kinetic_energy + t.internal_energy + mpm.boundary_ledger().energy;
}

double particle_l1_density(const mpm::ParticleSet& ps, const RiemannProblem& problem) {
  const verification::ExactRiemann exact(problem.left, problem.right, problem.gamma);
  double sum = 0.0, volume = 0.0;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double x = ps.position[0][p];
    if (x < 0.0 || x > 1.0) continue;
    const double v = ps.mass[p] / ps.density[p];
    sum += std::abs(ps.density[p] - exact.sample((x - 0.5) / problem.end).density) * v;
    volume += v;
  }
  return sum / volume / std::max(problem.left.density, problem.right.density);
}

}  // namespace mpfd::stability
