#pragma once
// A scene as the input of the 1D spherical MPM (design §2.3): its concentric
// regions about a centre become RadialLayers and its options SphericalOptions.
// Shared by `mpm_solver run` on a `domain.geometry: spherical` scene (V10) and
// the coupler's 1D start (`solver.afdmp.start: spherical`).

#include <vector>

#include "common/config/scene.hpp"
#include "mpm_solver/spherical/spherical_setup.hpp"

namespace mpfd::mpm::spherical {

/// The layers from r = 0 to outer_radius about `centre`: each shell takes the
/// last region (bodies in order, then charges) whose sphere holds it, else
/// `initial`; neighbouring shells of one region merge. Charges start at their
/// material's rho0 with e = E0 / rho0 and burn from the centre. Regions that do
/// not reach inside outer_radius, and bodies in `initial`'s state whatever
/// their shape (the background air body of an AFDMP scene), are left out.
/// Throws mpfd::Error naming a region that reaches inside but is not a sphere
/// about `centre`, one that moves, or a state its EOS cannot reach.
[[nodiscard]] std::vector<RadialLayer> layers_from_scene(const config::Scene& scene,
                                                         const config::Vec3& centre,
                                                         double outer_radius);

/// A `domain.geometry: spherical` scene: layers about the origin out to
/// domain.upper[0].
[[nodiscard]] std::vector<RadialLayer> layers_from_scene(const config::Scene& scene);

/// geometry spherical: h = the domain's cell size, particles per cell = the
/// regions' particles_per_axis, cfl = time.mpm_cfl(), shape and bulk viscosity of
/// solver.mpm, x_upper non_reflecting -> transmitting, outflow -> free.
/// Otherwise (the AFDMP 1D start): solver.afdmp.spherical's options, the bulk
/// viscosity of solver.mpm and a transmitting outer surface.
/// Throws mpfd::Error naming a key the spherical MPM cannot honour.
[[nodiscard]] SphericalOptions options_from_scene(const config::Scene& scene);

}  // namespace mpfd::mpm::spherical
