#pragma once
// The scene's initial condition sampled at cell centres: the background
// `initial` state, then every body in file order (a later body overwrites an
// earlier one), then every charge. Each cell takes the state of what holds its
// centre; sub-cell volume fractions are the FDM tracers' job (T §3.3).
//
// A charge starts as detonation products at the explosive's reference state
// (rho0, e0 = E0/rho0, at rest). Its pressure is the JWL pressure times the
// burn fraction F of T (3-2): F = 1 for an instantaneous burn, F = 0 for a
// program burn before the detonation front arrives.

#include <vector>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"

namespace mpfd::initial {

/// Primitive cell fields, structure of arrays, one value per cell in the
/// grid's cell order (x fastest).
struct CellFields {
  std::vector<double> density;                   // kg/m^3
  std::vector<double> velocity_x;                // m/s
  std::vector<double> velocity_y;                // m/s
  std::vector<double> velocity_z;                // m/s
  std::vector<double> specific_internal_energy;  // J/kg
  std::vector<double> pressure;                  // Pa
  std::vector<double> sound_speed;               // m/s
  std::vector<double> material;                  // index into Scene::materials
  std::vector<double> burn_fraction;             // F of T (3-2), 1 for inert material

  void resize(std::size_t cells);
};

/// The grid of the scene's domain.
grid::UniformGrid scene_grid(const config::Scene& scene);

/// Samples the scene's initial condition on `grid`. Throws mpfd::Error if a
/// state is not physical (density <= 0, or a pressure its EOS cannot reach).
CellFields initial_cells(const config::Scene& scene, const grid::UniformGrid& grid);

}  // namespace mpfd::initial
