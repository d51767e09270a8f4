#include "common/eos/jwl.hpp"

#include "common/eos/parameter_check.hpp"

namespace mpfd::eos {

void validate(const Jwl& eos) {
  constexpr std::string_view model = Jwl::name();
  require_parameter(eos.rho0 > 0.0, model, "rho0", eos.rho0, "> 0");
  require_parameter(eos.a >= 0.0, model, "a", eos.a, ">= 0");
  require_parameter(eos.b >= 0.0, model, "b", eos.b, ">= 0");
  require_parameter(eos.r2 > 0.0, model, "r2", eos.r2, "> 0");
  require_parameter(eos.r1 > eos.r2, model, "r1", eos.r1, "> r2 = " + format_parameter(eos.r2));
  require_parameter(eos.omega > 0.0 && eos.omega < 1.0, model, "omega", eos.omega, "in (0, 1)");
  require_parameter(eos.detonation_energy > 0.0, model, "detonation_energy", eos.detonation_energy,
                    "> 0");
}

}  // namespace mpfd::eos
