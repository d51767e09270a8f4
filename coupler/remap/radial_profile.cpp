#include "coupler/remap/radial_profile.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::remap {
namespace {

void require_size(std::span<const double> values, std::size_t shells, const char* name) {
  if (values.size() != shells)
    throw Error(std::string("radial profile: ") + name + " must have one value per shell (" +
                std::to_string(shells) + "), got " + std::to_string(values.size()));
}

}  // namespace

void check_profile(const RadialProfile& profile) {
  if (profile.edges.size() < 2)
    throw Error("radial profile: edges must hold at least 2 radii, got " +
                std::to_string(profile.edges.size()));
  const std::size_t shells = profile.edges.size() - 1;
  require(profile.edges[0] >= 0.0, "radial profile", "edges[0]", profile.edges[0], ">= 0");
  for (std::size_t k = 0; k < shells; ++k)
    require(profile.edges[k + 1] > profile.edges[k], "radial profile",
            "edges[" + std::to_string(k + 1) + "]", profile.edges[k + 1],
            "> edges[" + std::to_string(k) + "] = " + shortest_text(profile.edges[k]));
  require_size(profile.density, shells, "density");
  require_size(profile.velocity, shells, "velocity");
  require_size(profile.internal_energy, shells, "internal_energy");
  if (profile.material.size() != shells)
    throw Error("radial profile: material must have one index per shell (" +
                std::to_string(shells) + "), got " + std::to_string(profile.material.size()));
  for (std::size_t k = 0; k < shells; ++k) {
    require(profile.density[k] >= 0.0, "radial profile", "density[" + std::to_string(k) + "]",
            profile.density[k], ">= 0");
    require(profile.material[k] >= 0, "radial profile", "material[" + std::to_string(k) + "]",
            profile.material[k], ">= 0");
  }
  const bool has_stress = !profile.radial_stress.empty() || !profile.hoop_stress.empty();
  if (has_stress) {
    require_size(profile.radial_stress, shells, "radial_stress");
    require_size(profile.hoop_stress, shells, "hoop_stress");
  }
}

SphericalTotals profile_totals(const RadialProfile& profile) {
  check_profile(profile);
  SphericalTotals t;
  for (std::size_t k = 0; k + 1 < profile.edges.size(); ++k) {
    const double r0 = profile.edges[k];
    const double r1 = profile.edges[k + 1];
    const double mass =
        profile.density[k] * (4.0 * std::numbers::pi / 3.0) * (r1 * r1 * r1 - r0 * r0 * r0);
    const double u = profile.velocity[k];
    t.mass += mass;
    t.radial_impulse += mass * u;
    t.radial_impulse_magnitude += std::abs(mass * u);
    t.energy += mass * (profile.internal_energy[k] + 0.5 * u * u);
  }
  return t;
}

}  // namespace mpfd::coupler::remap
