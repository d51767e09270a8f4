#include "tests/verification/support/interface_sharpness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "common/core/error.hpp"

namespace mpfd::verification {
namespace {

constexpr double kQuarter = std::numbers::pi / 2;

/// Points on a lattice of spacing h over [0, 1)^2; products where inside(x, y).
struct Lattice {
  std::vector<double> x, y, products, air;
  template <typename Inside>
  Lattice(double h, Inside inside) {
    for (double px = h / 2; px < 1; px += h)
      for (double py = h / 2; py < 1; py += h) {
        x.push_back(px);
        y.push_back(py);
        const bool in = inside(px, py);
        products.push_back(in ? 1 : 0);
        air.push_back(in ? 0 : 1);
      }
  }
  [[nodiscard]] WeightedPoints view() const { return {x, y, products, air}; }
};

TEST(InterfaceSharpness, ACircleIsRoundAndSharpToTheLatticeSpacing) {
  const double h = 0.005, radius = 0.3;
  const Lattice lattice(h, [&](double x, double y) { return std::hypot(x, y) < radius; });
  const auto result = interface_sharpness(lattice.view(), 0, 0, 0, kQuarter, 9, 3 * h);
  EXPECT_NEAR(result.mean_radius, radius, h);
  EXPECT_LT(result.anisotropy, 2 * h / radius);
  EXPECT_EQ(result.air_inside, 0.0);
  EXPECT_EQ(result.products_outside, 0.0);
}

TEST(InterfaceSharpness, AnEllipseShowsItsAxisRatioAsAnisotropy) {
  const double h = 0.0025, a = 0.4, b = 0.3;
  const Lattice lattice(
      h, [&](double x, double y) { return (x / a) * (x / a) + (y / b) * (y / b) < 1; });
  // Sectors' radii run from about a (near the x axis) to about b (near the y axis).
  const auto result = interface_sharpness(lattice.view(), 0, 0, 0, kQuarter, 30, 3 * h);
  EXPECT_NEAR(result.radius.front(), a, 0.01);
  EXPECT_NEAR(result.radius.back(), b, 0.01);
  EXPECT_NEAR(result.anisotropy,
              (result.radius.front() - result.radius.back()) / result.mean_radius, 1e-12);
  EXPECT_GT(result.anisotropy, 0.25);
}

TEST(InterfaceSharpness, AirCarriedDeepIntoTheProductsIsCounted) {
  const double h = 0.005, radius = 0.3;
  Lattice lattice(h, [&](double x, double y) { return std::hypot(x, y) < radius; });
  // Every tenth products point deep inside (r < radius / 2) becomes air.
  double deep_air = 0;
  int seen = 0;
  for (std::size_t p = 0; p < lattice.x.size(); ++p)
    if (std::hypot(lattice.x[p], lattice.y[p]) < radius / 2 && seen++ % 10 == 0) {
      lattice.products[p] = 0;
      lattice.air[p] = 1;
      deep_air += 1;
    }
  double air_near = 0;
  for (std::size_t p = 0; p < lattice.x.size(); ++p)
    if (std::hypot(lattice.x[p], lattice.y[p]) <= radius + 3 * h) air_near += lattice.air[p];
  const auto result = interface_sharpness(lattice.view(), 0, 0, 0, kQuarter, 9, 3 * h);
  EXPECT_NEAR(result.mean_radius, radius, h);
  EXPECT_NEAR(result.air_inside, deep_air / air_near, 0.02);
  EXPECT_GT(result.air_inside, 0.1);
}

TEST(InterfaceSharpness, RefusesMismatchedArraysAndEmptySectors) {
  const std::vector<double> two = {0.1, 0.2}, one = {1};
  EXPECT_THROW((void)interface_sharpness({two, two, one, two}, 0, 0, 0, kQuarter, 1, 0), Error);
  const std::vector<double> x = {0.1}, y = {0.0}, products = {1}, air = {0};
  EXPECT_THROW((void)interface_sharpness({x, y, products, air}, 0, 0, 0, kQuarter, 1, 0), Error);
}

}  // namespace
}  // namespace mpfd::verification
