#include "mpm_solver/contact/common_normal.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

namespace mpfd::mpm::contact {
namespace {

// Default tolerance: a few units of round-off on O(1) values.
constexpr double kTol = 1e-14;

// d N_I / dx of the 1D linear shape function of node I at x, cell size h.
double shape_gradient(double x, double node, double h) {
  if (std::abs(x - node) >= h) return 0;
  return x < node ? 1 / h : -1 / h;
}

TEST(CommonNormal, MassGradientOfABodyPointsOutOfIt) {
  // Body A fills x < 0.95 with particles; node I at x = 1 sits beyond its surface,
  // body B fills x > 1.05. T (2-23) must give n̂^A = +x and n̂^B = -x.
  const double h = 1, node = 1;
  std::array<Vec<1>, 2> gradient{Vec<1>::Zero(), Vec<1>::Zero()};
  for (int p = 0; p < 19; ++p) {
    const double spacing = 0.05, mass = 0.1;
    gradient[0](0) += mass * shape_gradient(0.025 + spacing * p, node, h);
    gradient[1](0) += mass * shape_gradient(1.075 + spacing * p, node, h);
  }
  EXPECT_GT(gradient[0](0), 0);
  EXPECT_LT(gradient[1](0), 0);
  EXPECT_EQ(*common_normal<1>(gradient, 0), Vec<1>(1));
  EXPECT_EQ(*common_normal<1>(gradient, 1), Vec<1>(-1));
}

TEST(CommonNormal, TakesTheNamedBodysUnitGradient) {
  // T (2-24): the normal body's own surface decides, whatever B's gradient says.
  const std::array<Vec<3>, 2> gradient{Vec<3>(3, 0, 4), Vec<3>(0, -7, 1)};
  const Vec<3> n = *common_normal<3>(gradient, 0);
  EXPECT_NEAR((n - Vec<3>(0.6, 0, 0.8)).norm(), 0, kTol);
  const Vec<3> m = *common_normal<3>(gradient, 1);
  EXPECT_NEAR((m - Vec<3>(0, -7, 1) / std::sqrt(50.0)).norm(), 0, kTol);
}

TEST(CommonNormal, InsideTheNormalBodyFallsBackOnTheOthersReversed) {
  const std::array<Vec<2>, 3> gradient{Vec<2>(0, 0), Vec<2>(0, -2), Vec<2>(0, -1)};
  EXPECT_NEAR((*common_normal<2>(gradient, 0) - Vec<2>(0, 1)).norm(), 0, kTol);
}

TEST(CommonNormal, NoneWhenEveryGradientVanishes) {
  const std::array<Vec<2>, 2> gradient{Vec<2>::Zero(), Vec<2>::Zero()};
  EXPECT_FALSE(common_normal<2>(gradient, 1).has_value());
}

}  // namespace
}  // namespace mpfd::mpm::contact
