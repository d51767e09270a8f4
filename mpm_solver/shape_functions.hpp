#pragma once
// One-dimensional shape-function weights of a particle on a uniform grid; the
// 3D weight of a node is the product over the axes (tensor product), which is
// how both the trilinear function (2-7) and box GIMP factor.
//
// Positions are given in grid units, xi = (x - origin) / h, so node n sits at
// xi = n. An axis that is not active has one node layer with weight 1 and no
// gradient (a 1D or 2D run is the same code).

#include <algorithm>
#include <cmath>

namespace mpfd::mpm {

/// Weights and derivatives of the nodes first, first + 1, ... along one axis.
template <int Width>
struct AxisWeights {
  int first = 0;                ///< grid index of the first node (may be -1 for GIMP)
  double weight[Width] = {};    ///< N or S [-]
  double gradient[Width] = {};  ///< dN/dx [1/m]
};

/// Trilinear MPM, T (2-7) along one axis: the two nodes of the cell holding xi.
inline void linear_weights(double xi, double inverse_spacing, AxisWeights<2>& out) {
  const double base = std::floor(xi);
  const double f = xi - base;
  out.first = static_cast<int>(base);
  out.weight[0] = 1.0 - f;
  out.weight[1] = f;
  out.gradient[0] = -inverse_spacing;
  out.gradient[1] = inverse_spacing;
}

/// uGIMP weight S_Ip (W (2-57), (2-58)) of a node at distance r (grid units)
/// from a particle of half-width a (grid units, 0 < a <= 1/2), r = x_p - x_I: the closed form
/// of Bardenhagen & Kober (2004) quoted in SEED001-NOTES §1.6. Returns S and
/// sets dS/dr (per grid unit).
inline double gimp_weight(double r, double a, double& slope) {
  const double d = std::abs(r);
  const double sign = r < 0.0 ? -1.0 : 1.0;
  if (d < a) {
    slope = -r / a;
    return 1.0 - (r * r + a * a) / (2.0 * a);
  }
  if (d < 1.0 - a) {
    slope = -sign;
    return 1.0 - d;
  }
  if (d < 1.0 + a) {
    const double t = 1.0 + a - d;
    slope = -sign * t / (2.0 * a);
    return t * t / (4.0 * a);
  }
  slope = 0.0;
  return 0.0;
}

/// uGIMP along one axis. With a <= 1/2 at most three nodes have a nonzero
/// weight: those around the node nearest to xi, at signed distance u in
/// [-1/2, 1/2) from it. gimp_weight() of r = u + 1, u, u - 1 reduces to the
/// forms below, written without branches (selects) because particles
/// scatter over every case and branches would mispredict.
inline void gimp_weights(double xi, double half_width, double inverse_spacing,
                         AxisWeights<3>& out) {
  const double a = half_width;
  const double nearest = std::floor(xi + 0.5);
  const double u = xi - nearest;
  out.first = static_cast<int>(nearest) - 1;
  const double inverse_4a = 0.25 / a;
  // Node below (r = u + 1 >= 1/2): 1 - r when r < 1 - a, else (1 + a - r)^2 / (4a).
  const double below = std::max(a - u, 0.0);
  out.weight[0] = u < -a ? -u : below * below * inverse_4a;
  out.gradient[0] = (u < -a ? -1.0 : -2.0 * below * inverse_4a) * inverse_spacing;
  // The nearest node (|r| = |u| <= 1/2 <= 1 - a).
  const bool inside = std::abs(u) < a;
  out.weight[1] = inside ? 1.0 - (u * u + a * a) * 2.0 * inverse_4a : 1.0 - std::abs(u);
  out.gradient[1] = (inside ? -u * 4.0 * inverse_4a : (u < 0.0 ? 1.0 : -1.0)) * inverse_spacing;
  // Node above (r = u - 1 <= -1/2), the mirror image.
  const double above = std::max(a + u, 0.0);
  out.weight[2] = u > a ? u : above * above * inverse_4a;
  out.gradient[2] = (u > a ? 1.0 : 2.0 * above * inverse_4a) * inverse_spacing;
}

}  // namespace mpfd::mpm
