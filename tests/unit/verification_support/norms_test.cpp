#include "tests/verification/support/norms.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/core/error.hpp"

namespace mpfd::verification {
namespace {

constexpr double kNormsRoundOff = 1.0e-14;

std::vector<double> centre_values(int n, double x_min, double x_max, double (*f)(double)) {
  std::vector<double> u(static_cast<std::size_t>(n));
  const double dx = (x_max - x_min) / n;
  for (int i = 0; i < n; ++i) u[static_cast<std::size_t>(i)] = f(x_min + (i + 0.5) * dx);
  return u;
}

TEST(L1Error, ConstantOffsetGivesTheOffsetForBothReferences) {
  const std::vector<double> u(50, 2.5);
  const auto exact = [](double) { return 2.0; };
  EXPECT_NEAR(l1_error_at_centres(u, -1.0, 3.0, exact), 0.5, kNormsRoundOff);
  EXPECT_NEAR(l1_error_of_cell_averages(u, -1.0, 3.0, exact), 0.5, kNormsRoundOff);
}

TEST(L1Error, CentreValuesOfAParabolaDifferFromCellAveragesByDxSquaredOver12) {
  // (1/dx) int x^2 dx over a cell = x_i^2 + dx^2 / 12.
  const int n = 40;
  const double dx = 2.0 / n;
  const auto square = [](double x) { return x * x; };
  const std::vector<double> u = centre_values(n, 0.0, 2.0, square);
  EXPECT_NEAR(l1_error_at_centres(u, 0.0, 2.0, square), 0.0, kNormsRoundOff);
  EXPECT_NEAR(l1_error_of_cell_averages(u, 0.0, 2.0, square, 2), dx * dx / 12.0, kNormsRoundOff);
  EXPECT_NEAR(l1_error_of_cell_averages(u, 0.0, 2.0, square, 1), 0.0, kNormsRoundOff)
      << "one Gauss point is the centre";
}

TEST(L1Error, GaussRuleOfNPointsIsExactForDegree2NMinus1) {
  // Exact cell averages of x^5 and x^7: (b^6 - a^6) / (6 dx), (b^8 - a^8) / (8 dx).
  const int n = 7;
  const double x_min = -0.3;
  const double x_max = 1.1;
  const double dx = (x_max - x_min) / n;
  std::vector<double> quintic(n);
  std::vector<double> septic(n);
  for (int i = 0; i < n; ++i) {
    const double a = x_min + i * dx;
    const double b = a + dx;
    quintic[static_cast<std::size_t>(i)] = (std::pow(b, 6) - std::pow(a, 6)) / (6.0 * dx);
    septic[static_cast<std::size_t>(i)] = (std::pow(b, 8) - std::pow(a, 8)) / (8.0 * dx);
  }
  const auto x5 = [](double x) { return std::pow(x, 5); };
  const auto x7 = [](double x) { return std::pow(x, 7); };
  EXPECT_NEAR(l1_error_of_cell_averages(quintic, x_min, x_max, x5, 3), 0.0, kNormsRoundOff);
  EXPECT_NEAR(l1_error_of_cell_averages(septic, x_min, x_max, x7, 4), 0.0, kNormsRoundOff);
  EXPECT_NEAR(l1_error_of_cell_averages(septic, x_min, x_max, x7, 9), 0.0, kNormsRoundOff);
  EXPECT_GT(l1_error_of_cell_averages(septic, x_min, x_max, x7, 3), 1.0e-8)
      << "3 points are not exact for degree 7";
}

TEST(L1Error, IsNormalisedByDomainLength) {
  // A unit error in 1 of 10 cells is an L1 error of 0.1 whatever the domain.
  std::vector<double> u(10, 0.0);
  u[3] = 1.0;
  const auto zero = [](double) { return 0.0; };
  EXPECT_NEAR(l1_error_at_centres(u, 0.0, 1.0, zero), 0.1, kNormsRoundOff);
  EXPECT_NEAR(l1_error_at_centres(u, 0.0, 250.0, zero), 0.1, kNormsRoundOff);
}

TEST(L1Error, RejectsEmptyGridsAndBadRules) {
  const auto zero = [](double) { return 0.0; };
  const std::vector<double> none;
  const std::vector<double> one(1, 0.0);
  EXPECT_THROW((void)l1_error_at_centres(none, 0.0, 1.0, zero), Error);
  EXPECT_THROW((void)l1_error_at_centres(one, 1.0, 1.0, zero), Error);
  EXPECT_THROW((void)l1_error_of_cell_averages(one, 0.0, 1.0, zero, 0), Error);
}

}  // namespace
}  // namespace mpfd::verification
