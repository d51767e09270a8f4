#pragma once
// Internal: the checks that span sections of a parsed scene (material
// references, unique names, points and zones inside the domain, the solver
// method against the zones). Each part is checked only if it parsed cleanly,
// so one mistake does not cascade into many messages.

#include "common/config/diagnostics.hpp"
#include "common/config/scene.hpp"

namespace mpfd::config {

void check_scene(const Scene& scene, Diagnostics& diagnostics);

/// domain.geometry: spherical (scene_checks_spherical.cpp): a 1D radial line
/// of concentric spheres that mpm_solver run advances with the spherical MPM.
void check_spherical_geometry(const Scene& scene, Diagnostics& diagnostics);

/// solver.method: cfdmp (scene_checks_cfdmp.cpp): every body with a strength
/// model lies in the MPM zone at least 4 cells past the FDM zone: its ghost
/// layers and the cell whose particles reach the ghost cells' outer nodes.
void check_cfdmp_structures(const Scene& scene, Diagnostics& diagnostics);

/// solver.method: afdmp (scene_checks_afdmp.cpp): a charge, the FSI zone and
/// what it holds, and the ball the 1D start of `start: spherical` fills.
void check_afdmp(const Scene& scene, Diagnostics& diagnostics);

}  // namespace mpfd::config
