#pragma once
// Primitive cell fields derived from the conserved state, for output and
// gauges: velocity, specific internal energy, pressure and sound speed from
// the EOS of each cell's material. Arrays in the grid's cell order.

#include <vector>

#include "common/eos/any_eos.hpp"
#include "fdm_solver/euler_state.hpp"

namespace mpfd::fdm {

struct PrimitiveFields {
  std::vector<double> velocity_x, velocity_y, velocity_z;  // m/s
  std::vector<double> specific_internal_energy;            // J/kg
  std::vector<double> pressure;                            // Pa
  std::vector<double> sound_speed;                         // m/s
  std::vector<double> material;                            // index, as a number; -1 in a mixed cell

  /// Fills every field from `state` (resizing only on first use).
  void compute(const EulerState& state, const std::vector<eos::AnyEos>& eos);
};

}  // namespace mpfd::fdm
