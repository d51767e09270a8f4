#pragma once
// The material of a particle the coupler makes from FDM material crossing the
// coupling face. T (4-15)...(4-18) give its mass, momentum and energy, not its
// material; the FDM's strip export carries no volume fractions, but it does
// carry the cell's pressure. So the particle gets, among the fluids the scene
// fills (initial.material and the bodies' materials without strength), the
// one whose EOS at the particle's density and specific internal energy comes
// closest to the pressure of the FDM cell it is made in (k-w+1, on the zone's
// side: the particle's own place, T (4-17)): air stays air, and
// JWL detonation products (p ~ 0.3 rho e where air gives 0.4 rho e) stay
// products. One fluid in the scene: always that one.

#include <cstdint>
#include <vector>

#include "common/config/scene.hpp"

namespace mpfd::coupler {

class InjectedMaterial {
 public:
  explicit InjectedMaterial(const config::Scene& scene);

  /// Index into scene.materials for a particle of density rho [kg/m^3] and
  /// specific internal energy e [J/kg] from an FDM cell at pressure p [Pa].
  [[nodiscard]] std::uint32_t choose(double rho, double e, double p) const;

 private:
  const config::Scene& scene_;
  std::vector<std::uint32_t> fluids_;  ///< candidates; fluids_[0] = initial.material
};

}  // namespace mpfd::coupler
