#include "coupler/handoff/detonation_trigger.hpp"

#include <algorithm>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handoff {

double reaction_fraction(double time, double ignition_time, double detonation_velocity,
                         double length) {
  require(detonation_velocity > 0.0, "reaction_fraction", "detonation velocity D",
          detonation_velocity, "> 0");
  require(length > 0.0, "reaction_fraction", "characteristic length h", length, "> 0");
  if (time < ignition_time) return 0.0;
  return std::min(1.0, (time - ignition_time) * detonation_velocity / (1.5 * length));  // T (3-2)
}

bool detonation_complete(std::span<const double> reaction_fraction, std::span<const int> material,
                         std::span<const int> explosive_materials) {
  if (reaction_fraction.size() != material.size())
    throw Error("detonation_complete: reaction_fraction must have one value per particle (" +
                std::to_string(material.size()) + "), got " +
                std::to_string(reaction_fraction.size()));
  for (std::size_t p = 0; p < material.size(); ++p) {
    const bool explosive = std::find(explosive_materials.begin(), explosive_materials.end(),
                                     material[p]) != explosive_materials.end();
    if (explosive && !(reaction_fraction[p] >= 1.0)) return false;
  }
  return true;
}

}  // namespace mpfd::coupler::handoff
