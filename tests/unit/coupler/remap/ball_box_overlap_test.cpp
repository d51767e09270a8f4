#include "coupler/remap/ball_box_overlap.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "common/core/error.hpp"

namespace mpfd::coupler::remap {
namespace {

double overlap3(std::array<double, 3> lo, std::array<double, 3> hi, double r) {
  return ball_box_overlap(lo, hi, r);
}
double overlap2(std::array<double, 2> lo, std::array<double, 2> hi, double r) {
  return ball_box_overlap(lo, hi, r);
}

// Midpoint rule in x, y with the exact z chord: an independent check whose
// error falls as the number of columns grows.
double column_quadrature(std::array<double, 3> lo, std::array<double, 3> hi, double r, int n) {
  const double dx = (hi[0] - lo[0]) / n;
  const double dy = (hi[1] - lo[1]) / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = lo[0] + (i + 0.5) * dx;
      const double y = lo[1] + (j + 0.5) * dy;
      const double h2 = r * r - x * x - y * y;
      if (h2 <= 0.0) continue;
      const double top = std::min(hi[2], std::sqrt(h2));
      const double bottom = std::max(lo[2], -std::sqrt(h2));
      if (top > bottom) sum += (top - bottom) * dx * dy;
    }
  return sum;
}

TEST(BallBoxOverlap, Box_holding_the_ball_gives_its_volume) {
  const double r = 0.37;
  EXPECT_NEAR(overlap3({-1, -1, -1}, {1, 1, 1}, r), 4.0 / 3.0 * std::numbers::pi * r * r * r,
              1e-15);
  EXPECT_NEAR(overlap2({-1, -1}, {1, 1}, r), std::numbers::pi * r * r, 1e-15);
}

TEST(BallBoxOverlap, Octant_and_cap_match_their_closed_forms) {
  EXPECT_NEAR(overlap3({0, 0, 0}, {2, 2, 2}, 1.0), std::numbers::pi / 6.0, 1e-15);
  const double a = 0.6;  // cap x >= a of the unit ball: pi (1 - a)^2 (2 + a) / 3
  EXPECT_NEAR(overlap3({a, -2, -2}, {2, 2, 2}, 1.0),
              std::numbers::pi * (1 - a) * (1 - a) * (2 + a) / 3.0, 1e-15);
  // Disc segment y >= a: acos(a) - a sqrt(1 - a^2).
  EXPECT_NEAR(overlap2({-2, a}, {2, 2}, 1.0), std::acos(a) - a * std::sqrt(1 - a * a), 1e-15);
}

TEST(BallBoxOverlap, Agrees_with_column_quadrature_on_cut_boxes) {
  const std::array<std::array<double, 6>, 4> boxes{{{-0.3, 0.1, 0.2, 0.5, 0.9, 1.1},
                                                    {0.55, 0.4, -0.2, 0.8, 0.7, 0.35},
                                                    {-1.1, -0.4, -0.4, -0.6, 0.4, 0.1},
                                                    {0.3, 0.3, 0.3, 0.9, 0.8, 0.7}}};
  for (const auto& b : boxes) {
    const std::array<double, 3> lo{b[0], b[1], b[2]};
    const std::array<double, 3> hi{b[3], b[4], b[5]};
    const double exact = overlap3(lo, hi, 1.0);
    // Column quadrature error ~ n^-1.5 at the spherical rim: 2e-6 at n = 2000.
    EXPECT_NEAR(exact, column_quadrature(lo, hi, 1.0, 2000), 2e-6);
  }
}

TEST(BallBoxOverlap, Cells_of_a_grid_sum_to_the_ball_volume_to_round_off) {
  const int n = 24;
  const double h = 2.4 / n;
  const double r = 1.07;
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        sum += overlap3({-1.2 + i * h, -1.2 + j * h, -1.2 + k * h},
                        {-1.2 + (i + 1) * h, -1.2 + (j + 1) * h, -1.2 + (k + 1) * h}, r);
  EXPECT_NEAR(sum / (4.0 / 3.0 * std::numbers::pi * r * r * r), 1.0, 1e-13);
}

TEST(BallBoxOverlap, Inverted_box_is_an_error) {
  EXPECT_THROW((void)overlap3({1, 0, 0}, {0, 1, 1}, 1.0), Error);
}

}  // namespace
}  // namespace mpfd::coupler::remap
