#include "common/eos/polynomial.hpp"

#include <utility>

#include "common/core/require.hpp"

namespace mpfd::eos {

void validate(const Polynomial& eos) {
  constexpr std::string_view model = Polynomial::name();
  require(eos.rho0 > 0.0, model, "rho0", eos.rho0, "> 0");
  require(eos.a1 > 0.0, model, "a1", eos.a1, "> 0 (the bulk modulus in compression)");
  require(eos.t1 > 0.0, model, "t1", eos.t1, "> 0 (the bulk modulus in tension)");
  for (const auto& [parameter, value] :
       {std::pair{"a2", eos.a2}, std::pair{"a3", eos.a3}, std::pair{"b0", eos.b0},
        std::pair{"b1", eos.b1}, std::pair{"t2", eos.t2}}) {
    require(true, model, parameter, value, "finite");
  }
}

}  // namespace mpfd::eos
