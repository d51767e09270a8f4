#include "common/eos/mie_gruneisen.hpp"

#include "common/core/require.hpp"

namespace mpfd::eos {

void validate(const MieGruneisen& eos) {
  constexpr std::string_view model = MieGruneisen::name();
  require(eos.rho0 > 0.0, model, "rho0", eos.rho0, "> 0");
  require(eos.c0 > 0.0, model, "c0", eos.c0, "> 0");
  // S < 1 is rare but real (some porous and geological materials); S <= 0
  // would make the shock speed fall with the particle speed.
  require(eos.s > 0.0, model, "s", eos.s, "> 0");
  require(eos.gamma0 >= 0.0, model, "gamma0", eos.gamma0, ">= 0");
}

}  // namespace mpfd::eos
