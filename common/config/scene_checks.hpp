#pragma once
// Internal: the checks that span sections of a parsed scene (material
// references, unique names, points and zones inside the domain, the solver
// method against the zones). Each part is checked only if it parsed cleanly,
// so one mistake does not cascade into many messages.

#include "common/config/diagnostics.hpp"
#include "common/config/scene.hpp"

namespace mpfd::config {

void check_scene(const Scene& scene, Diagnostics& diagnostics);

}  // namespace mpfd::config
