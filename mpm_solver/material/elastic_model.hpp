#pragma once
// Linear elastic strength (Hooke's law on the deviator, T (2-21)):
//   s^{n+1} = s^n (Jaumann-rotated by the step) + 2 G dev(Delta eps),
// the pressure from the material's EOS, the energy by (2-4) with the
// deviatoric work, and c^2 = (K + 4G/3) / rho. No yield, no failure.

#include <string>

#include "common/eos/any_eos.hpp"
#include "mpm_solver/material/constitutive_model.hpp"

namespace mpfd::mpm {

class ElasticModel final : public ConstitutiveModel {
 public:
  /// shear_modulus G [Pa].
  ElasticModel(eos::AnyEos eos, double shear_modulus);

  void initialise(double rho, MaterialPoint& point) const override;
  void update(const StrainStep& step, MaterialPoint& point) const override;
  [[nodiscard]] std::string_view name() const override { return name_; }

 private:
  eos::AnyEos eos_;
  double shear_modulus_;
  std::string name_;
};

}  // namespace mpfd::mpm
