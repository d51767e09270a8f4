#include "mpm_solver/spherical/gauss_legendre.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::mpm::spherical {

QuadratureRule gauss_legendre(int n) {
  if (n < 1) throw Error("gauss_legendre: point count must be >= 1, got " + std::to_string(n));
  QuadratureRule rule;
  rule.points.resize(static_cast<std::size_t>(n));
  rule.weights.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    // Chebyshev-like first guess of the i-th largest root, then Newton on P_n.
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0;
      double p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      // p1 = P_n(x), p0 = P_{n-1}(x) (also for n = 1).
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    const auto slot = static_cast<std::size_t>(n - 1 - i);
    rule.points[slot] = x;
    rule.weights[slot] = 2.0 / ((1.0 - x * x) * derivative * derivative);
  }
  return rule;
}

}  // namespace mpfd::mpm::spherical
