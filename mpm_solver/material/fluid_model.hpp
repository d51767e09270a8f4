#pragma once
// A material without strength: gases, detonation products, liquids. The
// pressure comes from the EOS alone; an explosive's pressure is scaled by the
// program-burn fraction, p = F p_EOS (T (3-1)).

#include "common/eos/any_eos.hpp"
#include "mpm_solver/material/constitutive_model.hpp"

namespace mpfd::mpm {

class FluidModel final : public ConstitutiveModel {
 public:
  explicit FluidModel(eos::AnyEos eos) : eos_(eos) {}

  void initialise(double rho, MaterialPoint& point) const override;
  void update(const StrainStep& step, MaterialPoint& point) const override;
  [[nodiscard]] std::string_view name() const override { return eos::name(eos_); }

 private:
  eos::AnyEos eos_;
};

}  // namespace mpfd::mpm
