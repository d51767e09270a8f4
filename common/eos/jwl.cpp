#include "common/eos/jwl.hpp"

#include "common/core/require.hpp"

namespace mpfd::eos {

void validate(const Jwl& eos) {
  constexpr std::string_view model = Jwl::name();
  require(eos.rho0 > 0.0, model, "rho0", eos.rho0, "> 0");
  require(eos.a >= 0.0, model, "a", eos.a, ">= 0");
  require(eos.b >= 0.0, model, "b", eos.b, ">= 0");
  require(eos.r2 > 0.0, model, "r2", eos.r2, "> 0");
  require(eos.r1 > eos.r2, model, "r1", eos.r1, "> r2 = " + shortest_text(eos.r2));
  require(eos.omega > 0.0 && eos.omega < 1.0, model, "omega", eos.omega, "in (0, 1)");
  require(eos.detonation_energy > 0.0, model, "detonation_energy", eos.detonation_energy, "> 0");
}

}  // namespace mpfd::eos
