#pragma once
// Root of a scalar function on a bracket [lo, hi] over which it changes sign:
// Newton steps with a forward-difference slope, replaced by bisection
// whenever a step would leave the bracket or fails to halve the step before
// last (Numerical Recipes' rtsafe). Every iterate stays inside the bracket,
// which shrinks each iteration. A point kernel: no allocation, no throw.

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpfd::fdm {

/// A residual and the size it is compared with: converged when
/// |value| <= tolerance * scale.
struct Residual {
  double value;
  double scale;
};

struct RootResult {
  double x;
  int iterations;
  bool converged;  ///< false: the iteration limit came first
};

/// f: double -> Residual; f_lo is f(lo).value, of the opposite sign to f(hi).
template <class F>
[[nodiscard]] RootResult bracketed_newton(const F& f, double lo, double hi, double f_lo,
                                          double tolerance, int max_iterations) {
  constexpr double kSlopeStep = 1e-7;  // relative; slope error ~1e-7 keeps Newton fast
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double x = 0.5 * (lo + hi);
  double step_before_last = hi - lo;
  double last_step = hi - lo;
  for (int it = 1; it <= max_iterations; ++it) {
    const Residual r = f(x);
    if (std::abs(r.value) <= tolerance * r.scale) return {x, it, true};
    if ((r.value < 0.0) == (f_lo < 0.0)) {
      lo = x;
      f_lo = r.value;
    } else {
      hi = x;
    }
    if (hi - lo <= 4.0 * kEps * std::max(std::abs(lo), std::abs(hi)))
      return {x, it, true};  // the bracket is at round-off width
    const double h = kSlopeStep * std::max(std::abs(x), std::numeric_limits<double>::min());
    const double slope = (f(x + h).value - r.value) / h;
    const double newton = x - r.value / slope;
    const bool take_newton = std::isfinite(newton) && newton > lo && newton < hi &&
                             std::abs(newton - x) <= 0.5 * step_before_last;
    const double next = take_newton ? newton : 0.5 * (lo + hi);
    step_before_last = last_step;
    last_step = std::abs(next - x);
    x = next;
  }
  return {x, max_iterations, false};
}

}  // namespace mpfd::fdm
