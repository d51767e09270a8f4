#include "mpm_solver/shape_functions.hpp"

#include <gtest/gtest.h>

#include <random>

namespace mpfd::mpm {
namespace {

TEST(LinearWeights, PartitionOfUnityAndZeroGradientSum) {
  AxisWeights<2> w;
  linear_weights(3.25, 10.0, w);
  EXPECT_EQ(w.first, 3);
  EXPECT_DOUBLE_EQ(w.weight[0], 0.75);
  EXPECT_DOUBLE_EQ(w.weight[1], 0.25);
  EXPECT_DOUBLE_EQ(w.gradient[0] + w.gradient[1], 0.0);
  EXPECT_DOUBLE_EQ(w.gradient[1], 10.0);
}

TEST(GimpWeights, KnownValuesOfTheClosedForm) {
  double slope = 0.0;
  // a = 1/4 (2 particles per cell): S(0) = 1 - a/2, S(1/2) = 1/2, S(1) = a/4, S(1.25) = 0.
  EXPECT_DOUBLE_EQ(gimp_weight(0.0, 0.25, slope), 0.875);
  EXPECT_DOUBLE_EQ(slope, 0.0);
  EXPECT_DOUBLE_EQ(gimp_weight(0.5, 0.25, slope), 0.5);
  EXPECT_DOUBLE_EQ(slope, -1.0);
  EXPECT_DOUBLE_EQ(gimp_weight(1.0, 0.25, slope), 0.0625);
  EXPECT_DOUBLE_EQ(gimp_weight(1.25, 0.25, slope), 0.0);
}

TEST(GimpWeights, PartitionOfUnityAndGradientMatchesFiniteDifference) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> xi(0.0, 20.0);
  for (const double a : {0.125, 0.25, 0.5}) {
    for (int trial = 0; trial < 200; ++trial) {
      const double x = xi(rng);
      AxisWeights<3> w;
      gimp_weights(x, a, 4.0, w);
      double sum = 0.0, gradient_sum = 0.0;
      for (int k = 0; k < 3; ++k) {
        sum += w.weight[k];
        gradient_sum += w.gradient[k];
        // dS/dx by central differences of the same node's weight.
        const double h = 1e-6;
        double s = 0.0;
        const double r = x - (w.first + k);
        const double fd = (gimp_weight(r + h, a, s) - gimp_weight(r - h, a, s)) / (2 * h) * 4.0;
        EXPECT_NEAR(w.gradient[k], fd, 1e-5) << "a " << a << " x " << x << " node " << k;
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      EXPECT_NEAR(gradient_sum, 0.0, 1e-12);
    }
  }
}

TEST(GimpWeights, TendsToLinearAwayFromNodesForSmallParticles) {
  AxisWeights<3> g;
  gimp_weights(5.5, 0.01, 1.0, g);  // mid-cell: the particle sees only nodes 5 and 6
  AxisWeights<2> l;
  linear_weights(5.5, 1.0, l);
  EXPECT_EQ(g.first, 5);
  EXPECT_NEAR(g.weight[0], l.weight[0], 1e-14);
  EXPECT_NEAR(g.weight[1], l.weight[1], 1e-14);
  EXPECT_EQ(g.weight[2], 0.0);
}

}  // namespace
}  // namespace mpfd::mpm
