#pragma once
// The primitive state of a 1D ideal-gas flow, shared by the reference solutions.

namespace mpfd::verification {

/// Density, velocity and pressure in any consistent units (SI in MPFD:
/// kg/m^3, m/s, Pa).
struct PrimitiveState {
  double density;
  double velocity;
  double pressure;
};

}  // namespace mpfd::verification
