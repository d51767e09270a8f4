#include "mpm_solver/spherical/gauss_legendre.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mpm_solver/spherical/radial_shape.hpp"

namespace mpfd::mpm::spherical {
namespace {

TEST(GaussLegendre, TwoPointRuleIsPlusMinusOneOverRootThree) {
  const QuadratureRule rule = gauss_legendre(2);
  EXPECT_NEAR(rule.points[0], -1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(rule.points[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(rule.weights[0], 1.0, 1e-14);
  EXPECT_NEAR(rule.weights[1], 1.0, 1e-14);
}

TEST(GaussLegendre, FourPointRuleIntegratesDegreeSevenExactly) {
  const QuadratureRule rule = gauss_legendre(4);
  double x6 = 0.0;
  double x7 = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    x6 += rule.weights[i] * std::pow(rule.points[i], 6);
    x7 += rule.weights[i] * std::pow(rule.points[i], 7);
  }
  EXPECT_NEAR(x6, 2.0 / 7.0, 1e-14);
  EXPECT_NEAR(x7, 0.0, 1e-14);
}

// The GIMP moments of radial_shape.hpp against their definitions: partition of
// unity, and B_I + 2 C_I = [N_I r^2]_D / V_D (what makes uniform stress exact).
TEST(GimpWeights, MomentsSatisfyPartitionOfUnityAndTheDivergenceIdentity) {
  const double h = 0.01;
  const double l = h / 4.0;
  for (const double r : {0.0025, 0.0101, 0.2349, 0.5001}) {
    const RadialWeights w = gimp_weights(r, h, l);
    const double a = r - l;
    const double b = r + l;
    const double volume = (b * b * b - a * a * a) / 3.0;
    double sum = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      sum += w.value[k];
      const double node = static_cast<double>(w.first + k) * h;
      const auto hat = [&](double x) { return std::max(0.0, 1.0 - std::abs(x - node) / h); };
      const double boundary = (hat(b) * b * b - hat(a) * a * a) / volume;
      EXPECT_NEAR(w.gradient[k] + 2.0 * w.hoop[k], boundary, 1e-9 / h) << "r = " << r;
    }
    EXPECT_NEAR(sum, 1.0, 1e-13) << "r = " << r;
  }
}

}  // namespace
}  // namespace mpfd::mpm::spherical
