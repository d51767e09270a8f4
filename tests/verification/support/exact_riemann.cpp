#include "tests/verification/support/exact_riemann.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::verification {
namespace {

constexpr double kRelativeTolerance = 1.0e-12;
constexpr int kMaxNewtonIterations = 100;

struct PressureFunction {
  double value;
  double derivative;
};

// f_K(p) and f_K'(p) for the side with state w and sound speed a:
// T (4.6)-(4.8) and (4.37).
PressureFunction side_function(double p, const PrimitiveState& w, double a, double gamma) {
  if (p > w.pressure) {
    const double a_k = 2.0 / ((gamma + 1.0) * w.density);           // T (4.8)
    const double b_k = (gamma - 1.0) / (gamma + 1.0) * w.pressure;  // T (4.8)
    const double root = std::sqrt(a_k / (p + b_k));
    return {(p - w.pressure) * root,                             // T (4.6)
            root * (1.0 - 0.5 * (p - w.pressure) / (b_k + p))};  // T (4.37)
  }
  const double ratio = p / w.pressure;
  return {
      2.0 * a / (gamma - 1.0) * (std::pow(ratio, (gamma - 1.0) / (2.0 * gamma)) - 1.0),  // T (4.6)
      std::pow(ratio, -(gamma + 1.0) / (2.0 * gamma)) / (w.density * a)};                // T (4.37)
}

// Adaptive initial guess of T section 4.3.2 (Toro's ratio threshold Q_user = 2).
double initial_guess(const PrimitiveState& l, const PrimitiveState& r, double a_l, double a_r,
                     double gamma) {
  const double du = r.velocity - l.velocity;
  const double p_min = std::min(l.pressure, r.pressure);
  const double p_max = std::max(l.pressure, r.pressure);
  const double p_pv =
      std::max(0.0, 0.5 * (l.pressure + r.pressure) -
                        0.125 * du * (l.density + r.density) * (a_l + a_r));  // T (4.47)
  if (p_max / p_min <= 2.0 && p_min <= p_pv && p_pv <= p_max) return p_pv;
  if (p_pv < p_min) {
    const double z = (gamma - 1.0) / (2.0 * gamma);
    return std::pow((a_l + a_r - 0.5 * (gamma - 1.0) * du) /
                        (a_l / std::pow(l.pressure, z) + a_r / std::pow(r.pressure, z)),
                    1.0 / z);  // T (4.46)
  }
  const auto g = [&](const PrimitiveState& w) {
    return std::sqrt(2.0 / ((gamma + 1.0) * w.density) /
                     (p_pv + (gamma - 1.0) / (gamma + 1.0) * w.pressure));
  };
  return (g(l) * l.pressure + g(r) * r.pressure - du) / (g(l) + g(r));  // T (4.48)
}

}  // namespace

ExactRiemann::ExactRiemann(PrimitiveState left, PrimitiveState right, double gamma)
    : left_(left), right_(right), gamma_(gamma) {
  constexpr std::string_view where = "ExactRiemann";
  require(gamma > 1.0, where, "gamma", gamma, "> 1");
  require(left.density > 0.0, where, "left density", left.density, "> 0");
  require(left.pressure > 0.0, where, "left pressure", left.pressure, "> 0");
  require(std::isfinite(left.velocity), where, "left velocity", left.velocity, "finite");
  require(right.density > 0.0, where, "right density", right.density, "> 0");
  require(right.pressure > 0.0, where, "right pressure", right.pressure, "> 0");
  require(std::isfinite(right.velocity), where, "right velocity", right.velocity, "finite");

  sound_speed_left_ = std::sqrt(gamma * left.pressure / left.density);
  sound_speed_right_ = std::sqrt(gamma * right.pressure / right.density);
  const double du = right.velocity - left.velocity;
  const double du_critical = 2.0 * (sound_speed_left_ + sound_speed_right_) / (gamma - 1.0);
  require(du_critical > du, where, "u_R - u_L", du,
          "< 2 (a_L + a_R) / (gamma - 1) = " + shortest_text(du_critical) +
              " (pressure positivity, Toro (4.40); vacuum is generated)");

  const double p_floor = kRelativeTolerance * std::min(left.pressure, right.pressure);
  double p =
      std::max(p_floor, initial_guess(left, right, sound_speed_left_, sound_speed_right_, gamma));
  bool converged = false;
  for (int k = 0; k < kMaxNewtonIterations && !converged; ++k) {
    const PressureFunction fl = side_function(p, left, sound_speed_left_, gamma);
    const PressureFunction fr = side_function(p, right, sound_speed_right_, gamma);
    // Newton step, T (4.44); f is increasing and concave (T section 4.3.1), so
    // an overshoot below zero is halved back towards the root.
    double p_next = p - (fl.value + fr.value + du) / (fl.derivative + fr.derivative);
    if (p_next <= 0.0) p_next = 0.5 * p;
    converged = 2.0 * std::abs(p_next - p) / (p_next + p) < kRelativeTolerance;
    p = p_next;
  }
  if (!converged) {
    throw Error(
        "ExactRiemann: Newton iteration for the star pressure did not reach relative "
        "change 1e-12 in " +
        std::to_string(kMaxNewtonIterations) + " iterations (last p = " + shortest_text(p) + ")");
  }
  star_pressure_ = p;
  const PressureFunction fl = side_function(p, left, sound_speed_left_, gamma);
  const PressureFunction fr = side_function(p, right, sound_speed_right_, gamma);
  star_velocity_ = 0.5 * (left.velocity + right.velocity) + 0.5 * (fr.value - fl.value);  // T (4.9)

  const double gm = (gamma - 1.0) / (gamma + 1.0);
  if (p > left.pressure) {
    const double ratio = p / left.pressure;
    star_density_left_ = left.density * (ratio + gm) / (gm * ratio + 1.0);  // T (4.50)
    const double speed =
        left.velocity - sound_speed_left_ * std::sqrt((gamma + 1.0) / (2.0 * gamma) * ratio +
                                                      (gamma - 1.0) / (2.0 * gamma));  // T (4.52)
    left_wave_ = {true, speed, speed};
  } else {
    const double ratio = p / left.pressure;
    star_density_left_ = left.density * std::pow(ratio, 1.0 / gamma);  // T (4.53)
    const double a_star =
        sound_speed_left_ * std::pow(ratio, (gamma - 1.0) / (2.0 * gamma));            // T (4.54)
    left_wave_ = {false, left.velocity - sound_speed_left_, star_velocity_ - a_star};  // T (4.55)
  }
  if (p > right.pressure) {
    const double ratio = p / right.pressure;
    star_density_right_ = right.density * (ratio + gm) / (gm * ratio + 1.0);  // T (4.57)
    const double speed =
        right.velocity + sound_speed_right_ * std::sqrt((gamma + 1.0) / (2.0 * gamma) * ratio +
                                                        (gamma - 1.0) / (2.0 * gamma));  // T (4.59)
    right_wave_ = {true, speed, speed};
  } else {
    const double ratio = p / right.pressure;
    star_density_right_ = right.density * std::pow(ratio, 1.0 / gamma);  // T (4.60)
    const double a_star =
        sound_speed_right_ * std::pow(ratio, (gamma - 1.0) / (2.0 * gamma));  // T (4.61)
    right_wave_ = {false, right.velocity + sound_speed_right_,
                   star_velocity_ + a_star};  // T (4.62)
  }
}

PrimitiveState ExactRiemann::sample(double s) const {
  return s <= star_velocity_ ? sample_left(s) : sample_right(s);
}

PrimitiveState ExactRiemann::sample_left(double s) const {
  if (s <= left_wave_.head_speed) return left_;
  if (left_wave_.is_shock || s >= left_wave_.tail_speed) {
    return {star_density_left_, star_velocity_, star_pressure_};
  }
  const double g = gamma_;
  const double c =
      2.0 / (g + 1.0) + (g - 1.0) / ((g + 1.0) * sound_speed_left_) * (left_.velocity - s);
  return {left_.density * std::pow(c, 2.0 / (g - 1.0)),                                  // T (4.56)
          2.0 / (g + 1.0) * (sound_speed_left_ + 0.5 * (g - 1.0) * left_.velocity + s),  // T (4.56)
          left_.pressure * std::pow(c, 2.0 * g / (g - 1.0))};                            // T (4.56)
}

PrimitiveState ExactRiemann::sample_right(double s) const {
  if (s >= right_wave_.head_speed) return right_;
  if (right_wave_.is_shock || s <= right_wave_.tail_speed) {
    return {star_density_right_, star_velocity_, star_pressure_};
  }
  const double g = gamma_;
  const double c =
      2.0 / (g + 1.0) - (g - 1.0) / ((g + 1.0) * sound_speed_right_) * (right_.velocity - s);
  return {
      right_.density * std::pow(c, 2.0 / (g - 1.0)),                                    // T (4.63)
      2.0 / (g + 1.0) * (-sound_speed_right_ + 0.5 * (g - 1.0) * right_.velocity + s),  // T (4.63)
      right_.pressure * std::pow(c, 2.0 * g / (g - 1.0))};                              // T (4.63)
}

}  // namespace mpfd::verification
