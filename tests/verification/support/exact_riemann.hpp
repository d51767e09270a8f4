#pragma once
// Exact solution of the Riemann problem for the 1D Euler equations of an ideal
// gas, p = (gamma - 1) rho e, after Toro, "Riemann Solvers and Numerical
// Methods for Fluid Dynamics", 3rd ed. (2009), chapter 4 ("T" below).
//
// The star-region pressure p* is the root of the pressure function
//   f(p) = f_L(p) + f_R(p) + (u_R - u_L)                      T (4.5)
//   f_K(p) = (p - p_K) sqrt(A_K / (p + B_K))                   p > p_K (shock)
//          = 2 a_K / (gamma - 1) [(p / p_K)^((gamma-1)/(2 gamma)) - 1]
//                                                              p <= p_K (rarefaction)
//   A_K = 2 / ((gamma + 1) rho_K),  B_K = (gamma - 1) / (gamma + 1) p_K
//                                                              T (4.6)-(4.8)
// found by Newton iteration (derivatives T (4.37)) from the adaptive guess of
// T section 4.3.2 (PVRS (4.47), else two-rarefaction (4.46) or two-shock
// (4.48)) until the relative change 2|p_k - p_{k-1}| / (p_k + p_{k-1}) < 1e-12.
// Then u* = (u_L + u_R) / 2 + (f_R(p*) - f_L(p*)) / 2          T (4.9)
// and the solution at S = (x - x0) / t is sampled as in T section 4.5.
//
// Omitted: vacuum (initial or generated) states. Data violating the
// pressure-positivity condition T (4.40) throw mpfd::Error.

#include "tests/verification/support/primitive_state.hpp"

namespace mpfd::verification {

/// One of the two nonlinear waves of the solution (T Fig. 4.2). For a shock the
/// head and tail speeds are both the shock speed; for a rarefaction the head is
/// the edge facing the undisturbed state.
struct Wave {
  bool is_shock;
  double head_speed;
  double tail_speed;
};

class ExactRiemann {
 public:
  /// Solves the problem for states left (x < x0) and right (x > x0) at t = 0;
  /// throws mpfd::Error for non-positive density or pressure, gamma <= 1,
  /// vacuum generation or a Newton iteration that does not converge.
  ExactRiemann(PrimitiveState left, PrimitiveState right, double gamma);

  /// The solution at similarity variable s = (x - x0) / t.
  [[nodiscard]] PrimitiveState sample(double s) const;

  [[nodiscard]] double star_pressure() const { return star_pressure_; }
  /// Also the speed of the contact discontinuity.
  [[nodiscard]] double star_velocity() const { return star_velocity_; }
  [[nodiscard]] double star_density_left() const { return star_density_left_; }
  [[nodiscard]] double star_density_right() const { return star_density_right_; }
  [[nodiscard]] Wave left_wave() const { return left_wave_; }
  [[nodiscard]] Wave right_wave() const { return right_wave_; }

 private:
  [[nodiscard]] PrimitiveState sample_left(double s) const;
  [[nodiscard]] PrimitiveState sample_right(double s) const;

  PrimitiveState left_;
  PrimitiveState right_;
  double gamma_;
  double sound_speed_left_;
  double sound_speed_right_;
  double star_pressure_;
  double star_velocity_;
  double star_density_left_;
  double star_density_right_;
  Wave left_wave_;
  Wave right_wave_;
};

}  // namespace mpfd::verification
