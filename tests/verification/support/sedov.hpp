#pragma once
// Sedov-Taylor point blast in an ideal gas (p = (gamma - 1) rho e) of uniform
// density rho0 and zero pressure: energy E released at r = 0, t = 0 in planar
// (nu = 1), cylindrical (nu = 2) or spherical (nu = 3) geometry. References:
// Sedov, "Similarity and Dimensional Methods in Mechanics" (1959), ch. IV ("S");
// Kamm & Timmes, "On efficient generation of numerically robust Sedov
// solutions", LA-UR-07-2849 (2007) ("KT").
//
// The shock radius is R(t) = xi0 (E t^2 / rho0)^(1/(nu+2)), its speed
// D = delta R / t with delta = 2 / (nu + 2). With lambda = r / R and
//   u = D U(lambda),  rho = rho0 G(lambda),  p = rho0 D^2 P(lambda),
// mass, momentum and entropy conservation become (w = U - lambda)
//   w G' + G (U' + (nu - 1) U / lambda) = 0
//   w U' + P' / G = (nu / 2) U
//   w (P'/P - gamma G'/G) = nu
// with the strong-shock values at lambda = 1
//   G = (gamma + 1) / (gamma - 1),  U = P = 2 / (gamma + 1),
// and the energy integral (S ch. IV; zero energy flux through lambda = const)
//   w (P / (gamma - 1) + G U^2 / 2) + P U = 0.
// They are integrated inwards in ln(lambda) (RK4, step doubling, tolerance
// 1e-12), U being projected onto the energy integral after each step (it
// removes the mode U/lambda - 1/gamma ~ lambda^-nu that grows inwards), until
// (w/c)^2 = w^2 G / (gamma P) is 1e-9 of its post-shock value. Below that the
// centre asymptotics (S; KT) hold:
//   U = lambda / gamma,  P = P_c,  G ~ lambda^(nu / (gamma - 1)).
// The energy then fixes xi0:
//   E = sigma_nu rho0 D^2 R^nu I,  I = int_0^1 (G U^2 / 2 + P / (gamma - 1)) lambda^(nu-1) dlambda
//   alpha = sigma_nu delta^2 I = xi0^-(nu+2),  i.e.  E = alpha rho0 R^(nu+2) / t^2,
// with sigma = 1, 2 pi, 4 pi: E is the energy in 0 <= r <= R per unit area
// (planar: half that of a slab |x| < R), per unit length (cylindrical) or in
// total (spherical), as in KT. For gamma = 1.4 alpha = 0.538743, 0.984074,
// 0.851072, as a 1e-9 quadrature of KT's closed form gives (KT's Table 4
// lists 0.538548, 0.984041, 0.851060).
//
// Omitted: non-uniform ambient density, ambient pressure, and the singular
// (spherical gamma = 7) and vacuum (spherical gamma > 7) solutions of KT,
// which throw mpfd::Error.

#include <array>
#include <vector>

#include "tests/verification/support/primitive_state.hpp"

namespace mpfd::verification {

/// The dimensionless profile at lambda = r / R: rho / rho0, u / D, p / (rho0 D^2).
struct SedovProfile {
  double density;
  double velocity;
  double pressure;
};

class SedovSolution {
 public:
  /// Integrates the similarity ODEs; throws mpfd::Error for gamma <= 1,
  /// nu not in {1, 2, 3} or spherical gamma >= 7.
  SedovSolution(double gamma, int nu);

  [[nodiscard]] double gamma() const { return gamma_; }
  [[nodiscard]] int nu() const { return nu_; }
  /// E = alpha rho0 R^(nu+2) / t^2.
  [[nodiscard]] double alpha() const { return alpha_; }
  /// R(t) = xi0 (E t^2 / rho0)^(1/(nu+2)).
  [[nodiscard]] double xi0() const { return xi0_; }

  [[nodiscard]] double shock_radius(double energy, double rho0, double t) const;
  [[nodiscard]] double shock_speed(double energy, double rho0, double t) const;
  /// Profile at 0 <= lambda <= 1 (cubic Hermite in ln(lambda) between
  /// integration steps; centre asymptotics below the last step).
  [[nodiscard]] SedovProfile profile(double lambda) const;
  /// State at distance r >= 0 from the source at time t > 0; (rho0, 0, 0)
  /// ahead of the shock.
  [[nodiscard]] PrimitiveState sample(double r, double energy, double rho0, double t) const;

 private:
  struct Node {
    double log_lambda;
    std::array<double, 3> y;     // ln G, U, ln P
    std::array<double, 3> dyds;  // d/d(ln lambda)
  };

  double gamma_;
  int nu_;
  double alpha_ = 0.0;
  double xi0_ = 0.0;
  std::vector<Node> nodes_;  // ln(lambda) decreasing from 0
};

/// xi0 for the given gamma and geometry (integrates the ODEs on each call).
[[nodiscard]] double sedov_xi0(double gamma, int nu);
/// R(t) = xi0 (E t^2 / rho0)^(1/(nu+2)).
[[nodiscard]] double sedov_shock_radius(double energy, double rho0, double t, double gamma, int nu);

/// State just behind a strong shock of speed D into gas at rest with density
/// rho0 and negligible pressure (the Rankine-Hugoniot conditions in the limit
/// p0 -> 0; the values of the ODEs above at lambda = 1):
/// rho = rho0 (gamma + 1) / (gamma - 1), u = 2 D / (gamma + 1), p = 2 rho0 D^2 / (gamma + 1).
[[nodiscard]] PrimitiveState strong_shock_state(double rho0, double shock_speed, double gamma);

}  // namespace mpfd::verification
