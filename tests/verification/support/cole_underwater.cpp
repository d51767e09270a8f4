#include "tests/verification/support/cole_underwater.hpp"

#include <cmath>

#include "common/core/require.hpp"

namespace mpfd::verification {

double cole_peak_pressure(double charge_mass, double distance) {
  require(charge_mass > 0.0, "Cole", "charge mass W [kg]", charge_mass, "> 0");
  require(distance > 0.0, "Cole", "distance R [m]", distance, "> 0");
  return 52.4e6 * std::pow(std::cbrt(charge_mass) / distance, 1.13);
}

}  // namespace mpfd::verification
