#include "coupler/remap/ball_box_overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::coupler::remap {
namespace {

constexpr double kPi = std::numbers::pi;

double root_of_positive(double x) {
  return std::sqrt(std::max(x, 0.0));
}

// 1 - x^2 without cancellation near |x| = 1.
double one_minus_square(double x) {
  return (1.0 - x) * (1.0 + x);
}

// |unit disc ∩ {x >= a, y >= b}| for a, b >= 0. Angles as atan2 of the two
// legs: asin near 1 would lose half the digits.
double disc_corner(double a, double b) {
  if (a * a + b * b >= 1.0) return 0.0;
  const double wa = root_of_positive(one_minus_square(a));
  const double wb = root_of_positive(one_minus_square(b));
  return 0.5 * (0.5 * kPi - std::atan2(a, wa) - std::atan2(b, wb)) - 0.5 * (a * wa + b * wb) +
         a * b;
}

// A slice x = const of the unit ball and, for the two cut planes y = b and
// z = c, w_b = sqrt(1 - x^2 - b^2), w_c = sqrt(1 - x^2 - c^2).
struct Slice {
  double x;
  double w_b;
  double w_c;
};

// Antiderivative in x of (1 - x^2) asin(s / sqrt(1 - x^2)), by parts, with
// w = sqrt(1 - x^2 - s^2); valid while w is real.
double arcsine_slice_integral(double x, double s, double w) {
  if (s == 0.0) return 0.0;
  const double k2 = 1.0 - s * s;
  const double v = x - x * x * x / 3.0;
  const double j = (s / 3.0) * ((0.5 * k2 - 2.0) * std::atan2(x, w) - 0.5 * x * w) +
                   (2.0 / 3.0) * std::atan2(x * s, w);
  return v * std::atan2(s, w) - j;
}

// Antiderivative in x of s sqrt(1 - s^2 - x^2) / 2.
double chord_integral(double x, double s, double w) {
  return 0.25 * s * (x * w + (1.0 - s * s) * std::atan2(x, w));
}

// Antiderivative in x of disc_corner scaled to the slice of radius sqrt(1 - x^2).
double ball_corner_antiderivative(const Slice& at, double b, double c) {
  const double x = at.x;
  return 0.25 * kPi * (x - x * x * x / 3.0) - 0.5 * arcsine_slice_integral(x, c, at.w_c) -
         0.5 * arcsine_slice_integral(x, b, at.w_b) - chord_integral(x, c, at.w_c) -
         chord_integral(x, b, at.w_b) + b * c * x;
}

// |unit ball ∩ {x >= a, y >= b, z >= c}| for a, b, c >= 0. At the top
// x = sqrt(1 - b^2 - c^2) the slice legs are exactly w_b = c, w_c = b.
double ball_corner(double a, double b, double c) {
  if (a * a + b * b + c * c >= 1.0) return 0.0;
  const double top_q = b * b + c * c;
  const Slice top{std::sqrt(1.0 - top_q), c, b};
  const double q = one_minus_square(a);
  const Slice bottom{a, root_of_positive(q - b * b), root_of_positive(q - c * c)};
  return ball_corner_antiderivative(top, b, c) - ball_corner_antiderivative(bottom, b, c);
}

template <int D>
double corner(const std::array<double, D>& l) {
  if constexpr (D == 2) {
    return disc_corner(l[0], l[1]);
  } else {
    return ball_corner(l[0], l[1], l[2]);
  }
}

// |unit ball ∩ [lo, hi]| for a box in the first orthant (lo >= 0), by
// inclusion-exclusion over its corners.
template <int D>
double positive_box(const std::array<double, D>& lo, const std::array<double, D>& hi) {
  double sum = 0.0;
  for (int bits = 0; bits < (1 << D); ++bits) {
    std::array<double, D> l{};
    int sign = 1;
    for (int i = 0; i < D; ++i) {
      const bool high = (bits >> i) & 1;
      l[i] = high ? hi[i] : lo[i];
      if (high) sign = -sign;
    }
    sum += sign * corner<D>(l);
  }
  return std::max(sum, 0.0);
}

// |unit ball ∩ [lo, hi]|: reflect each axis into x_i >= 0, splitting a box
// that straddles x_i = 0, so that only first-orthant boxes are evaluated
// (no differences of large orthant volumes; 2^D corners for most cells).
template <int D>
double unit_overlap(std::array<double, D> lo, std::array<double, D> hi, int axis) {
  for (int i = axis; i < D; ++i) {
    if (hi[i] <= 0.0) {
      const double reflected_lo = -hi[i];
      hi[i] = -lo[i];
      lo[i] = reflected_lo;
    } else if (lo[i] < 0.0) {
      std::array<double, D> negative_hi = hi;
      negative_hi[i] = -lo[i];
      lo[i] = 0.0;
      std::array<double, D> negative_lo = lo;
      return unit_overlap<D>(lo, hi, i + 1) + unit_overlap<D>(negative_lo, negative_hi, i + 1);
    }
  }
  double near2 = 0.0;
  for (int i = 0; i < D; ++i) near2 += lo[i] * lo[i];
  if (near2 >= 1.0) return 0.0;
  return positive_box<D>(lo, hi);
}

template <int D>
double scaled_overlap(std::span<const double> lower, std::span<const double> upper, double radius) {
  std::array<double, D> lo{};
  std::array<double, D> hi{};
  for (int i = 0; i < D; ++i) {
    lo[i] = lower[i] / radius;
    hi[i] = upper[i] / radius;
  }
  return std::pow(radius, D) * unit_overlap<D>(lo, hi, 0);
}

}  // namespace

double ball_box_overlap(std::span<const double> lower, std::span<const double> upper,
                        double radius) {
  if (lower.size() != upper.size() || (lower.size() != 2 && lower.size() != 3))
    throw Error("ball_box_overlap: box dimension must be 2 or 3, got " +
                std::to_string(lower.size()) + " lower and " + std::to_string(upper.size()) +
                " upper bounds");
  for (std::size_t i = 0; i < lower.size(); ++i)
    if (!(lower[i] <= upper[i]))
      throw Error("ball_box_overlap: lower bound " + std::to_string(lower[i]) + " of axis " +
                  std::to_string(i) + " must not exceed the upper bound " +
                  std::to_string(upper[i]));
  if (radius <= 0.0) return 0.0;
  if (lower.size() == 2) return scaled_overlap<2>(lower, upper, radius);
  return scaled_overlap<3>(lower, upper, radius);
}

}  // namespace mpfd::coupler::remap
