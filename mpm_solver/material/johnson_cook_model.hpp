#pragma once
// Johnson-Cook plasticity (flow stress T (2-64), johnson_cook_flow_stress.hpp)
// on J2 radial return (radial_return.hpp), pressure from the material's EOS
// (Mie-Grueneisen T (2-65), (2-66), or any other solid EOS). Per step:
//   s_trial = s^n + 2 G dev(Delta eps); if sqrt(3/2)|s_trial| > sigma_y the
//   deviator returns to |s| = sqrt(2/3) sigma_y(eps_p + Delta eps_p, rate),
//   the rate being Delta eps_p / dt;
//   specific plastic work dW_p = sigma_y Delta eps_p v_avg (v = 1/rho), and the
//   adiabatic temperature rise dT = beta dW_p / c_p with the Taylor-Quinney
//   fraction beta = kTaylorQuinney; the temperature softens the next step.
// Optional failure strain eps_f: once eps_p >= eps_f, damage = 1 and the
// material keeps no deviatoric stress and no tension (p >= 0) from then on.
// Omitted: Johnson-Cook damage (D = sum Delta eps_p / eps_f(sigma*, rate, T)),
// heating from the volumetric work, spall by a pressure cut-off.

#include <string>

#include "common/config/scene.hpp"
#include "common/eos/any_eos.hpp"
#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/material/johnson_cook_flow_stress.hpp"

namespace mpfd::mpm {

/// Fraction of plastic work that heats the metal (Taylor-Quinney coefficient;
/// 0.9 is the value usually taken for metals; the rest is stored in the lattice).
inline constexpr double kTaylorQuinney = 0.9;

class JohnsonCookModel final : public ConstitutiveModel {
 public:
  /// history[kPlasticStrainRate]: the last step's Delta eps_p / dt [1/s], for output.
  static constexpr int kPlasticStrainRate = 0;

  JohnsonCookModel(eos::AnyEos eos, const config::JohnsonCook& parameters);

  [[nodiscard]] int history_count() const override { return 1; }
  void initialise(double rho, MaterialPoint& point) const override;
  void update(const StrainStep& step, MaterialPoint& point) const override;
  [[nodiscard]] std::string_view name() const override { return name_; }

 private:
  eos::AnyEos eos_;
  config::JohnsonCook parameters_;
  JohnsonCookFlowStress flow_stress_;
  std::string name_;
};

}  // namespace mpfd::mpm
