#include "tests/verification/support/convergence.hpp"

#include <cmath>

#include "common/core/require.hpp"

namespace mpfd::verification {

void ConvergenceStudy::add(double cells, double error) {
  constexpr std::string_view where = "ConvergenceStudy";
  require(cells > 0.0, where, "cell count", cells, "> 0");
  require(error > 0.0, where, "error", error, "> 0 (the orders use its logarithm)");
  require(cells_.empty() || cells != cells_.back(), where, "cell count", cells,
          "different from the previous entry's");
  cells_.push_back(cells);
  errors_.push_back(error);
}

std::vector<double> ConvergenceStudy::observed_orders() const {
  std::vector<double> orders;
  for (std::size_t i = 1; i < cells_.size(); ++i) {
    orders.push_back(std::log(errors_[i - 1] / errors_[i]) / std::log(cells_[i] / cells_[i - 1]));
  }
  return orders;
}

double ConvergenceStudy::fitted_order() const {
  return fit().order;
}

double ConvergenceStudy::fitted_constant() const {
  return fit().constant;
}

ConvergenceStudy::Fit ConvergenceStudy::fit() const {
  require(cells_.size() >= 2, "ConvergenceStudy", "number of entries",
          static_cast<double>(cells_.size()), ">= 2 for a fit");
  // Least squares for ln e = ln C - p ln N, in deviations from the means.
  const double n = static_cast<double>(cells_.size());
  double mean_x = 0.0;
  double mean_y = 0.0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    mean_x += std::log(cells_[i]) / n;
    mean_y += std::log(errors_[i]) / n;
  }
  double sxx = 0.0;
  double sxy = 0.0;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const double dx = std::log(cells_[i]) - mean_x;
    sxx += dx * dx;
    sxy += dx * (std::log(errors_[i]) - mean_y);
  }
  const double slope = sxy / sxx;
  return {-slope, std::exp(mean_y - slope * mean_x)};
}

}  // namespace mpfd::verification
