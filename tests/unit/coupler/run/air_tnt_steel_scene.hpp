#pragma once
// A scene for the coupler's material tests: air around TNT products (T Table 3.1)
// and a steel plate (elastic: not a fluid, so never an injected material).

namespace mpfd::coupler::testing {

inline constexpr const char* kAirTntSteelScene = R"(name: mix
time: {end: 1.0e-5}
domain: {lower: [0, 0, 0], upper: [1, 1, 0.01], cells: [10, 10, 1]}
materials:
  air: {eos: {type: ideal_gas, gamma: 1.4}}
  tnt:
    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3,
          E0: 6.993e9}
  steel:
    eos: {type: ideal_gas, gamma: 3.0}
    strength: {type: elastic, shear_modulus: 8.0e10}
initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}
bodies:
  - {name: products, material: tnt, density: 1630, specific_internal_energy: 4.2902e6,
     shape: {box: {lower: [0, 0, 0], upper: [0.2, 0.2, 0.01]}}}
  - {name: plate, material: steel, density: 7800, pressure: 1.0e5,
     shape: {box: {lower: [0.8, 0, 0], upper: [1, 1, 0.01]}}}
output: {interval: 1.0e-5}
)";

}  // namespace mpfd::coupler::testing
