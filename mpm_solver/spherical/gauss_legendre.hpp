#pragma once
// Gauss-Legendre points and weights on [-1, 1]: n points integrate polynomials
// up to degree 2n - 1 exactly. The spherical MPM seeds its particles there.

#include <vector>

namespace mpfd::mpm::spherical {

struct QuadratureRule {
  std::vector<double> points;   ///< ascending, in (-1, 1)
  std::vector<double> weights;  ///< sum to 2
};

/// The n-point rule (n >= 1), roots of P_n by Newton's method to round-off.
[[nodiscard]] QuadratureRule gauss_legendre(int n);

}  // namespace mpfd::mpm::spherical
