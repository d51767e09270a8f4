#include "tests/verification/support/convergence.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/core/error.hpp"
#include "tests/verification/support/norms.hpp"

namespace mpfd::verification {
namespace {

using ::testing::HasSubstr;

TEST(ConvergenceStudy, RecoversOrderAndConstantOfExactPowerLaw) {
  for (double p : {1.0, 2.0, 3.5}) {
    ConvergenceStudy study;
    for (double n : {16.0, 32.0, 64.0, 128.0, 256.0}) study.add(n, 0.7 * std::pow(n, -p));
    ASSERT_EQ(study.size(), 5u);
    const std::vector<double> orders = study.observed_orders();
    ASSERT_EQ(orders.size(), 4u);
    for (double q : orders) EXPECT_NEAR(q, p, 1.0e-12);
    EXPECT_NEAR(study.fitted_order(), p, 1.0e-12);
    EXPECT_NEAR(study.fitted_constant(), 0.7, 1.0e-12);
  }
}

TEST(ConvergenceStudy, ObservedOrdersUseConsecutivePairsAndFitIsLeastSquares) {
  // Errors 1, 1/2, 1/16 at N = 1, 2, 4: pairwise orders 1 and 3; the
  // least-squares slope through (0, 0), (ln 2, -ln 2), (2 ln 2, -4 ln 2) is -2.
  ConvergenceStudy study;
  study.add(1.0, 1.0);
  study.add(2.0, 0.5);
  study.add(4.0, 1.0 / 16.0);
  EXPECT_THAT(study.observed_orders(), ::testing::ElementsAre(::testing::DoubleNear(1.0, 1.0e-14),
                                                              ::testing::DoubleNear(3.0, 1.0e-14)));
  EXPECT_NEAR(study.fitted_order(), 2.0, 1.0e-14);
}

TEST(ConvergenceStudy, MeshSizeEntersAsItsInverse) {
  // error = 3 h^2 with N = 1/h.
  ConvergenceStudy study;
  for (double h : {0.1, 0.05, 0.02}) study.add(1.0 / h, 3.0 * h * h);
  EXPECT_NEAR(study.fitted_order(), 2.0, 1.0e-12);
  EXPECT_NEAR(study.fitted_constant(), 3.0, 1.0e-12);
}

TEST(ConvergenceStudy, RejectsEntriesWithoutALogarithm) {
  ConvergenceStudy study;
  try {
    study.add(10.0, 0.0);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("error must be > 0"));
  }
  EXPECT_THROW(study.add(-4.0, 1.0), Error);
  EXPECT_THROW(study.add(10.0, NAN), Error);
  study.add(10.0, 1.0);
  EXPECT_THROW(study.add(10.0, 0.5), Error);
  EXPECT_THROW((void)study.fitted_order(), Error);
  EXPECT_TRUE(study.observed_orders().empty());
}

// The house way to assert an order (docs/STYLE.md): a ConvergenceStudy over
// refinements and `rate > p - 0.1`. Here the exact solution is its own
// numerical solution: centre values of sin(2 pi x) differ from its cell
// averages by dx^2 f'' / 24, a second-order "error".
TEST(ConvergenceStudy, CentreValuesApproximateCellAveragesToSecondOrder) {
  const auto exact = [](double x) { return std::sin(2.0 * std::numbers::pi * x); };
  ConvergenceStudy study;
  for (int n : {20, 40, 80, 160, 320}) {
    std::vector<double> centres(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) centres[static_cast<std::size_t>(i)] = exact((i + 0.5) / n);
    study.add(n, l1_error_of_cell_averages(centres, 0.0, 1.0, exact));
  }
  for (double rate : study.observed_orders()) EXPECT_GT(rate, 2.0 - 0.1);
  EXPECT_GT(study.fitted_order(), 2.0 - 0.1);
}

}  // namespace
}  // namespace mpfd::verification
