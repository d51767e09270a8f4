// A served Euler zone leaves the structures to the MPM (served_zone.cpp): a body
// with a strength model keeps the scene's initial state in the FDM's cells
// instead of tension it cannot hold (found by bench/stability/random_scenes.py:
// every CFDMP scene with a solid stopped at step 0 in a cell never exchanged). The
// plate lies in the MPM zone beyond the FDM zone's ghost layers and the cell after, as the scene
// check asks; the FDM's grid still covers it.
#include <gtest/gtest.h>

#include "checkpoint_support.hpp"

namespace mpfd::fdm::testing {
namespace {

TEST(CoupledStructures, ASteelBodyIsLeftToTheMpmAndItsCellsHoldTheInitialAir) {
  const std::string scene =
      "name: plate\ntime: {end: 1.0e-4}\n"
      "domain: {lower: [0, 0, 0], upper: [0.1, 0.01, 0.01], cells: [20, 1, 1]}\n"
      "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "  steel:\n"
      "    eos: {type: mie_gruneisen, rho0: 7890, C0: 4569, S: 1.49, gamma0: 2.17}\n"
      "    strength: {type: elastic, shear_modulus: 8.18e10}\n"
      "initial: {material: air, density: 1.225, pressure: 1.0e5}\n"
      "bodies:\n"
      "  - {name: plate, material: steel, density: 7890, pressure: 0,\n"
      "     shape: {box: {lower: [0.085, 0, 0], upper: [0.1, 0.01, 0.01]}}}\n"
      "output: {interval: 1.0e-4}\n"
      "solver: {method: cfdmp}\n"
      "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.065, 0.01, 0.01]}\n"
      "  mpm: {lower: [0.04, 0, 0], upper: [0.1, 0.01, 0.01]}\n";
  const auto zone = zone_of(scene);
  EXPECT_TRUE(zone->scene.bodies.empty());
  const auto& rho = zone->solver.state().u[0];
  for (std::size_t c = 0; c < rho.size(); ++c) EXPECT_DOUBLE_EQ(rho[c], 1.225) << c;
  advance_stable(*zone, 3);  // air at rest stays at rest; no tension, no error
  for (std::size_t c = 0; c < rho.size(); ++c)
    EXPECT_DOUBLE_EQ(zone->solver.state().u[0][c], 1.225) << c;
}

}  // namespace
}  // namespace mpfd::fdm::testing
