#pragma once
// A single material point driven by prescribed strain increments: the
// particle arrays of one particle, and the steps the MPM step would hand a
// model for a few homogeneous deformation paths.

#include <array>
#include <cmath>

#include "mpm_solver/material/constitutive_model.hpp"

namespace mpfd::mpm::test_support {

struct PointStorage {
  Tensor3 s = Tensor3::Zero();
  double p = 0, e = 0, c = 0, eps = 0, wp = 0, d = 0, t = 293;
  std::array<double, 4> history{};
  MaterialPoint view() { return {s, p, e, c, eps, wp, d, t, history}; }
  /// Cauchy stress sigma = s - p I (no bulk viscosity in these tests).
  [[nodiscard]] Tensor3 stress() const { return s - p * Tensor3::Identity(); }
};

/// Uniaxial strain along x by d (d < 0 compresses): rho^{n+1} = rho^n / (1 + d), (2-20).
inline StrainStep uniaxial_strain(double rho_old, double d, double dt = 1e-7) {
  StrainStep step;
  step.dt = dt;
  step.density_old = rho_old;
  step.density_new = rho_old / (1.0 + d);
  step.strain_increment(0, 0) = d;
  return step;
}

/// Simple shear in the x-y plane by an engineering shear increment dgamma (no volume change).
inline StrainStep shear(double rho, double dgamma, double dt = 1e-7) {
  StrainStep step;
  step.dt = dt;
  step.density_old = rho;
  step.density_new = rho;
  step.strain_increment(0, 1) = step.strain_increment(1, 0) = 0.5 * dgamma;
  return step;
}

/// Isotropic volume change from rho_old to rho_new plus a shear increment dgamma.
inline StrainStep volume_and_shear(double rho_old, double rho_new, double dgamma,
                                   double dt = 1e-7) {
  StrainStep step = shear(rho_old, dgamma, dt);
  step.density_new = rho_new;
  // (2-20): tr(Delta eps) = rho^n / rho^{n+1} - 1, spread over the three axes.
  step.strain_increment.diagonal().setConstant((rho_old / rho_new - 1.0) / 3.0);
  return step;
}

}  // namespace mpfd::mpm::test_support
