#include "common/eos/ideal_gas.hpp"

#include "common/eos/parameter_check.hpp"

namespace mpfd::eos {

void validate(const IdealGas& eos) {
  require_parameter(eos.gamma > 1.0, IdealGas::name(), "gamma", eos.gamma, "> 1");
}

}  // namespace mpfd::eos
