#include "tests/verification/support/norms.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "common/core/require.hpp"

namespace mpfd::verification {
namespace {

void check_grid(std::span<const double> cells, double x_min, double x_max) {
  require(!cells.empty(), "L1 error", "number of cells", 0.0, "> 0");
  require(x_max > x_min, "L1 error", "x_max", x_max, "> x_min");
}

struct Quadrature {
  std::vector<double> nodes;  // on [-1, 1]
  std::vector<double> weights;
};

// Gauss-Legendre rule of n points: nodes are the roots of P_n, found by Newton
// from Chebyshev-like guesses; P_n by the three-term recurrence
// (k + 1) P_{k+1} = (2k + 1) x P_k - k P_{k-1}; weights 2 / ((1 - x^2) P_n'(x)^2)
// (Abramowitz & Stegun 25.4.29).
Quadrature gauss_legendre(int n) {
  Quadrature q;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 0.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p = 1.0;
      double p_previous = 0.0;
      for (int k = 0; k < n; ++k) {
        const double p_next = ((2.0 * k + 1.0) * x * p - k * p_previous) / (k + 1.0);
        p_previous = p;
        p = p_next;
      }
      derivative = n * (x * p - p_previous) / (x * x - 1.0);
      const double dx = p / derivative;
      x -= dx;
      if (std::abs(dx) < 1.0e-15) break;
    }
    q.nodes.push_back(x);
    q.weights.push_back(2.0 / ((1.0 - x * x) * derivative * derivative));
  }
  return q;
}

}  // namespace

double l1_error_at_centres(std::span<const double> cells, double x_min, double x_max,
                           const std::function<double(double)>& exact) {
  check_grid(cells, x_min, x_max);
  const double dx = (x_max - x_min) / static_cast<double>(cells.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    sum += std::abs(cells[i] - exact(x_min + (static_cast<double>(i) + 0.5) * dx));
  }
  return sum / static_cast<double>(cells.size());
}

double l1_error_of_cell_averages(std::span<const double> cells, double x_min, double x_max,
                                 const std::function<double(double)>& exact, int gauss_points) {
  check_grid(cells, x_min, x_max);
  require(gauss_points >= 1, "L1 error", "Gauss points", gauss_points, ">= 1");
  const Quadrature q = gauss_legendre(gauss_points);
  const double dx = (x_max - x_min) / static_cast<double>(cells.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const double centre = x_min + (static_cast<double>(i) + 0.5) * dx;
    double average = 0.0;
    for (std::size_t k = 0; k < q.nodes.size(); ++k) {
      average += 0.5 * q.weights[k] * exact(centre + 0.5 * dx * q.nodes[k]);
    }
    sum += std::abs(cells[i] - average);
  }
  return sum / static_cast<double>(cells.size());
}

}  // namespace mpfd::verification
