#pragma once
// What AFDMP puts into the FSI-zone cells at the MPM -> FDM handoff (design
// §3.5 H1 step 3): the FDM never advances them usefully before the FDM -> MPM
// handoff discards them (the FSI zone's air and structure come from the MPM,
// T §3.2.3), but it must hold a valid state: the scene's `initial` state
// (ambient air) and tracers_per_axis^d regular tracers of its material per
// cell, as the FDM seeds them (fdm_solver's seed_from_materials).

#include <array>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"
#include "coupler/handoff/sub_grid.hpp"

namespace mpfd::coupler::handoff {

struct AmbientState {
  int material = 0;                       ///< index into the scene's materials
  double density = 0.0;                   ///< [kg/m^3]
  std::array<double, 3> velocity{};       ///< [m/s]
  double specific_internal_energy = 0.0;  ///< [J/kg]
};

/// The scene's `initial` state; e from its pressure by the material's EOS
/// when the scene gives a pressure. Throws mpfd::Error naming the scene for
/// an unknown material or a pressure the EOS cannot reach.
[[nodiscard]] AmbientState ambient_state(const config::Scene& scene);

/// Sets the cells of `box` to rho, rho v, E = rho (e + |v|^2 / 2) (T (2-49));
/// `cells` holds the whole grid (grid order). Throws mpfd::Error on a size
/// mismatch or a box outside the grid.
void fill_ambient_cells(const grid::UniformGrid& grid, const CellBox& box,
                        const AmbientState& state, ConservedCells& cells);

/// Appends tracers_per_axis^d tracers of `material` at the sub-cell centres of
/// every cell of `box` (cells in grid order). Throws mpfd::Error for
/// tracers_per_axis < 1 or a box outside the grid.
void append_regular_tracers(const grid::UniformGrid& grid, const CellBox& box, int material,
                            int tracers_per_axis, TracerPoints& tracers);

}  // namespace mpfd::coupler::handoff
