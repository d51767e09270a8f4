#include "common/eos/ideal_gas.hpp"

#include "common/core/require.hpp"

namespace mpfd::eos {

void validate(const IdealGas& eos) {
  require(eos.gamma > 1.0, IdealGas::name(), "gamma", eos.gamma, "> 1");
}

}  // namespace mpfd::eos
