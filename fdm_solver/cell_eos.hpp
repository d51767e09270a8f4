#pragma once
// Pressure and sound speed of one cell by its own equation of state: its
// material's model, or its stiffened-gas fit if it is a mixed cell
// (mixture_eos.hpp). For code outside the sweep's inner loops.

#include <vector>

#include "common/eos/any_eos.hpp"
#include "fdm_solver/euler_state.hpp"
#include "fdm_solver/mixture_eos.hpp"

namespace mpfd::fdm {

[[nodiscard]] inline double cell_pressure(const EulerState& s,
                                          const std::vector<eos::AnyEos>& models, std::size_t cell,
                                          double rho, double e) {
  if (s.material[cell] == kMixedMaterial)
    return StiffenedGas{s.mix_gamma[cell], s.mix_pinf[cell]}.pressure(rho, e);
  return eos::pressure(models[s.material[cell]], rho, e);
}

[[nodiscard]] inline double cell_sound_speed(const EulerState& s,
                                             const std::vector<eos::AnyEos>& models,
                                             std::size_t cell, double rho, double e) {
  if (s.material[cell] == kMixedMaterial)
    return StiffenedGas{s.mix_gamma[cell], s.mix_pinf[cell]}.sound_speed(rho, e);
  return eos::sound_speed(models[s.material[cell]], rho, e);
}

}  // namespace mpfd::fdm
