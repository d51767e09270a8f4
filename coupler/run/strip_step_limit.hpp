#pragma once
// The coupled step's cap from the strip cells (docs/stability.md, "A strong
// shock entering the MPM zone"). A wave in strip_cells reaches the MPM zone
// within a step, so the step must resolve it at the MPM's CFL. The solvers'
// own proposals do not: the MPM's particles next to the face are still at rest,
// and the FDM's CFL counts split half steps (docs/fdm.md), so a strong shock
// entered the zone at about twice the MPM's Courant number and the particles
// next to the face turned unphysical.

#include <span>

#include "common/config/scene.hpp"
#include "coupler/handshake/index_box.hpp"
#include "coupler/run/injected_material.hpp"

namespace mpfd::coupler {

/// cfl * spacing / max over the cells of (c + |u|) [s], from each cell's density
/// rho [kg/m^3], momentum density [kg/(m^2 s)] and total energy density E [J/m^3];
/// c is the sound speed of the fluid `materials` picks for the cell (its pressure p
/// [Pa]). Cells with no mass or a non-finite speed are skipped (the FDM reports
/// those itself); infinity when no cell counts.
template <int Dim>
[[nodiscard]] double strip_step_limit(std::span<const double> rho,
                                      std::span<const handshake::Vec<Dim>> momentum,
                                      std::span<const double> energy,
                                      std::span<const double> pressure,
                                      const InjectedMaterial& materials, const config::Scene& scene,
                                      double cfl, double spacing);

}  // namespace mpfd::coupler
