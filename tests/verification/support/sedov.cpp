#include "tests/verification/support/sedov.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::verification {
namespace {

// State of the integration in s = ln(lambda): ln G, U, ln P and the running
// energy integral J(s) = int_0^s (G U^2 / 2 + P / (gamma - 1)) lambda^nu ds', so
// that I = -J(-infinity). The logarithms keep G and P positive where they fall
// as powers of lambda (G ~ lambda^(nu/(gamma-1)) at the centre).
using State = std::array<double, 4>;

constexpr double kTolerance = 1.0e-12;
constexpr double kMaxStep = 0.002;  // cubic Hermite profile: slopes to ~1e-7 relative
constexpr double kMinStep = 1.0e-12;
// The centre asymptotics take over once (w/c)^2 has fallen to this fraction of
// its post-shock value (gamma - 1) / (2 gamma); they hold to O((w/c)^2).
constexpr double kCentre = 1.0e-9;
constexpr double kLogLambdaMin = -60.0;  // gives up below lambda = 1e-26

State derivative(double s, const State& y, double gamma, int nu) {
  const double lambda = std::exp(s);
  const double u = y[1];
  const double w = u - lambda;
  const double inv_c2 = std::exp(y[0] - y[2]) / gamma;  // G / (gamma P) = 1 / c^2
  // The three ODEs of sedov.hpp solved for the derivatives, times lambda.
  const double du = (0.5 * nu * u * w * inv_c2 * lambda - nu * lambda / gamma + (nu - 1) * u) /
                    (w * w * inv_c2 - 1.0);
  const double divergence = du + (nu - 1) * u;  // lambda (U' + (nu - 1) U / lambda)
  return {-divergence / w, du, (nu * lambda - gamma * divergence) / w,
          (0.5 * std::exp(y[0]) * u * u + std::exp(y[2]) / (gamma - 1.0)) * std::pow(lambda, nu)};
}

State rk4_step(double s, const State& y, double h, double gamma, int nu) {
  const auto axpy = [](const State& a, double c, const State& b) {
    State r{};
    for (std::size_t i = 0; i < r.size(); ++i) r[i] = a[i] + c * b[i];
    return r;
  };
  const State k1 = derivative(s, y, gamma, nu);
  const State k2 = derivative(s + 0.5 * h, axpy(y, 0.5 * h, k1), gamma, nu);
  const State k3 = derivative(s + 0.5 * h, axpy(y, 0.5 * h, k2), gamma, nu);
  const State k4 = derivative(s + h, axpy(y, h, k3), gamma, nu);
  State r{};
  for (std::size_t i = 0; i < r.size(); ++i) {
    r[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
  }
  return r;
}

// Projects U onto Sedov's energy integral (sedov.hpp) at fixed lambda, G, P by
// Newton on g(U) = gamma U - lambda - (gamma - 1) (lambda - U) G U^2 / (2 P).
// Without it the inward integration amplifies errors in U/lambda as lambda^-nu.
double project_velocity(double u, double s, const State& y, double gamma) {
  const double lambda = std::exp(s);
  const double k = 0.5 * (gamma - 1.0) * std::exp(y[0] - y[2]);  // (gamma - 1) G / (2 P)
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double g = gamma * u - lambda - k * (lambda - u) * u * u;
    const double dg = gamma - k * (2.0 * lambda * u - 3.0 * u * u);
    const double du = g / dg;
    u -= du;
    if (std::abs(du) <= 1.0e-15 * std::abs(u)) break;
  }
  return u;
}

double geometry_factor(int nu) {
  switch (nu) {
    case 1:
      return 1.0;
    case 2:
      return 2.0 * std::numbers::pi;
    default:
      return 4.0 * std::numbers::pi;
  }
}

}  // namespace

SedovSolution::SedovSolution(double gamma, int nu) : gamma_(gamma), nu_(nu) {
  constexpr std::string_view where = "SedovSolution";
  require(gamma > 1.0, where, "gamma", gamma, "> 1");
  require(nu >= 1 && nu <= 3, where, "nu", nu, "1 (planar), 2 (cylindrical) or 3 (spherical)");
  require(nu != 3 || gamma < 7.0, where, "gamma", gamma,
          "< 7 in spherical geometry (the singular and vacuum solutions are not implemented)");

  const State shock{std::log((gamma + 1.0) / (gamma - 1.0)), 2.0 / (gamma + 1.0),
                    std::log(2.0 / (gamma + 1.0)), 0.0};
  // Absolute error scales: relative for G and P, post-shock values for U and J.
  const State scale{1.0, shock[1], 1.0, 2.0 / (gamma * gamma - 1.0)};
  const double centre_threshold = kCentre * (gamma - 1.0) / (2.0 * gamma);

  double s = 0.0;
  State y = shock;
  double h = -1.0e-3;
  const auto record = [&] {
    const State d = derivative(s, y, gamma, nu);
    nodes_.push_back({s, {y[0], y[1], y[2]}, {d[0], d[1], d[2]}});
  };
  const auto fail = [&](std::string_view what) {
    throw Error("SedovSolution: " + std::string(what) +
                " at lambda = " + shortest_text(std::exp(s)) + " (gamma = " + shortest_text(gamma) +
                ", nu = " + std::to_string(nu) + ")");
  };
  record();
  // RK4 with step doubling: the difference of one step h and two steps h/2 is
  // 15 times the error of the latter, which is then Richardson-corrected.
  for (;;) {
    const double w = y[1] - std::exp(s);
    if (w * w * std::exp(y[0] - y[2]) / gamma < centre_threshold) break;
    if (s < kLogLambdaMin) fail("the centre asymptotics were not reached");
    const State full = rk4_step(s, y, h, gamma, nu);
    const State half =
        rk4_step(s + 0.5 * h, rk4_step(s, y, 0.5 * h, gamma, nu), 0.5 * h, gamma, nu);
    double error = 0.0;
    for (std::size_t i = 0; i < y.size(); ++i) {
      error = std::max(error, std::abs(half[i] - full[i]) / (15.0 * scale[i]));
    }
    const bool valid = std::isfinite(error);
    const bool accepted = valid && error <= kTolerance;
    if (accepted) {
      s += h;
      for (std::size_t i = 0; i < y.size(); ++i) y[i] = half[i] + (half[i] - full[i]) / 15.0;
      y[1] = project_velocity(y[1], s, y, gamma);
      record();
    }
    const double factor =
        valid ? std::clamp(0.9 * std::pow(kTolerance / std::max(error, 1e-300), 0.2), 0.2, 4.0)
              : 0.25;
    h = std::max(h * factor, -kMaxStep);
    if (!accepted && std::abs(h) < kMinStep) fail("the step size fell below 1e-12");
  }

  // Energy below the last node from the centre asymptotics (sedov.hpp).
  const double lambda_c = std::exp(s);
  const double density_c = std::exp(y[0]);
  const double pressure_c = std::exp(y[2]);
  const double tail = pressure_c * std::pow(lambda_c, nu) / (nu * (gamma - 1.0)) +
                      density_c * std::pow(lambda_c, nu + 2) /
                          (2.0 * gamma * gamma * (nu / (gamma - 1.0) + nu + 2.0));
  const double delta = 2.0 / (nu + 2.0);
  alpha_ = geometry_factor(nu) * delta * delta * (tail - y[3]);
  xi0_ = std::pow(alpha_, -1.0 / (nu + 2.0));
}

double SedovSolution::shock_radius(double energy, double rho0, double t) const {
  constexpr std::string_view where = "SedovSolution";
  require(energy > 0.0, where, "energy", energy, "> 0");
  require(rho0 > 0.0, where, "rho0", rho0, "> 0");
  require(t >= 0.0, where, "t", t, ">= 0");
  return xi0_ * std::pow(energy * t * t / rho0, 1.0 / (nu_ + 2.0));
}

double SedovSolution::shock_speed(double energy, double rho0, double t) const {
  require(t > 0.0, "SedovSolution", "t", t, "> 0");
  return 2.0 / (nu_ + 2.0) * shock_radius(energy, rho0, t) / t;
}

SedovProfile SedovSolution::profile(double lambda) const {
  require(lambda >= 0.0 && lambda <= 1.0, "SedovSolution", "lambda = r / R", lambda, "in [0, 1]");
  const double s = std::log(lambda);
  const Node& last = nodes_.back();
  if (s <= last.log_lambda) {  // centre asymptotics (sedov.hpp)
    const double ds = s - last.log_lambda;
    return {std::exp(last.y[0] + nu_ / (gamma_ - 1.0) * ds), std::exp(s) / gamma_,
            std::exp(last.y[2])};
  }
  // Nodes run from ln(lambda) = 0 downwards: the first node below s ends the
  // interval, which cannot be the first node since s <= 0.
  const auto upper = std::upper_bound(nodes_.begin(), nodes_.end(), s,
                                      [](double v, const Node& n) { return v > n.log_lambda; });
  const Node& b = *upper;
  const Node& a = *(upper - 1);
  const double h = b.log_lambda - a.log_lambda;
  const double t = (s - a.log_lambda) / h;
  const double t2 = t * t;
  const double t3 = t2 * t;
  std::array<double, 3> y{};
  for (std::size_t i = 0; i < y.size(); ++i) {  // cubic Hermite in s
    y[i] = (2.0 * t3 - 3.0 * t2 + 1.0) * a.y[i] + (t3 - 2.0 * t2 + t) * h * a.dyds[i] +
           (-2.0 * t3 + 3.0 * t2) * b.y[i] + (t3 - t2) * h * b.dyds[i];
  }
  return {std::exp(y[0]), y[1], std::exp(y[2])};
}

PrimitiveState SedovSolution::sample(double r, double energy, double rho0, double t) const {
  require(r >= 0.0, "SedovSolution", "r", r, ">= 0");
  require(t > 0.0, "SedovSolution", "t", t, "> 0");
  const double radius = shock_radius(energy, rho0, t);
  if (r > radius) return {rho0, 0.0, 0.0};
  const double speed = shock_speed(energy, rho0, t);
  const SedovProfile f = profile(r / radius);
  return {rho0 * f.density, speed * f.velocity, rho0 * speed * speed * f.pressure};
}

double sedov_xi0(double gamma, int nu) {
  return SedovSolution(gamma, nu).xi0();
}

double sedov_shock_radius(double energy, double rho0, double t, double gamma, int nu) {
  return SedovSolution(gamma, nu).shock_radius(energy, rho0, t);
}

PrimitiveState strong_shock_state(double rho0, double shock_speed, double gamma) {
  require(rho0 > 0.0, "strong_shock_state", "rho0", rho0, "> 0");
  require(gamma > 1.0, "strong_shock_state", "gamma", gamma, "> 1");
  require(std::isfinite(shock_speed), "strong_shock_state", "shock speed", shock_speed, "finite");
  return {rho0 * (gamma + 1.0) / (gamma - 1.0), 2.0 * shock_speed / (gamma + 1.0),
          2.0 * rho0 * shock_speed * shock_speed / (gamma + 1.0)};
}

}  // namespace mpfd::verification
