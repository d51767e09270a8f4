#include "common/eos/polynomial.hpp"

#include <utility>

#include "common/eos/parameter_check.hpp"

namespace mpfd::eos {

void validate(const Polynomial& eos) {
  constexpr std::string_view model = Polynomial::name();
  require_parameter(eos.rho0 > 0.0, model, "rho0", eos.rho0, "> 0");
  require_parameter(eos.a1 > 0.0, model, "a1", eos.a1, "> 0 (the bulk modulus in compression)");
  require_parameter(eos.t1 > 0.0, model, "t1", eos.t1, "> 0 (the bulk modulus in tension)");
  for (const auto& [parameter, value] :
       {std::pair{"a2", eos.a2}, std::pair{"a3", eos.a3}, std::pair{"b0", eos.b0},
        std::pair{"b1", eos.b1}, std::pair{"t2", eos.t2}}) {
    require_parameter(true, model, parameter, value, "finite");
  }
}

}  // namespace mpfd::eos
