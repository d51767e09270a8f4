#include "common/eos/mie_gruneisen.hpp"

#include "common/eos/parameter_check.hpp"

namespace mpfd::eos {

void validate(const MieGruneisen& eos) {
  constexpr std::string_view model = MieGruneisen::name();
  require_parameter(eos.rho0 > 0.0, model, "rho0", eos.rho0, "> 0");
  require_parameter(eos.c0 > 0.0, model, "c0", eos.c0, "> 0");
  // S < 1 is rare but real (some porous and geological materials); S <= 0
  // would make the shock speed fall with the particle speed.
  require_parameter(eos.s > 0.0, model, "s", eos.s, "> 0");
  require_parameter(eos.gamma0 >= 0.0, model, "gamma0", eos.gamma0, ">= 0");
}

}  // namespace mpfd::eos
