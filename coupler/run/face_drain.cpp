#include "coupler/run/face_drain.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/require.hpp"

namespace mpfd::coupler {

std::string with_cause(const std::string& error, const std::string& cause) {
  return error + (error.ends_with('.') ? " " : ". ") + cause;
}

void FaceDrainWatch::observe(std::size_t face_cell, double density, double added_density,
                             double returned_mass, double cell_volume) {
  if (!(density > 0) || !(added_density < 0)) return;
  const double share = -added_density / density;
  if (share <= last_.share) return;
  last_ = {.face_cell = face_cell,
           .share = share,
           .density = density,
           .taken_back = -returned_mass,
           .particle_mass = std::max(0.0, added_density * cell_volume - returned_mass)};
  run_max_share_ = std::max(run_max_share_, share);
}

std::string FaceDrainWatch::cause_text(const std::string& cell) const {
  const FaceDrain& drain = worst();
  if (drain.share < kNamedShare) return {};
  const long percent = std::lround(100 * drain.share);
  return "Cause: a deposit of the coupler took " + std::to_string(percent) +
         " % of the mass of FDM cell " + cell + " beside the coupling face (density " +
         number_text(drain.density, 3) +
         " kg/m^3 before it): the FDM's flow out of the MPM zone through that face in the step, " +
         number_text(drain.taken_back, 3) +
         " kg, is taken back because particles crossing the face carry that material, and the "
         "particles that crossed brought " +
         number_text(drain.particle_mass, 3) +
         " kg. The MPM zone's gas leaves it more slowly than the FDM's, so the FDM cell empties; a "
         "smaller time.cfl or a finer grid does not cure this (docs/stability.md, random scenes "
         "case 5). Keep gas that flows out of the MPM zone on the FDM's side: move the zone face "
         "(zones.mpm) so that the flow there enters the zone, or run a scene without a structure "
         "with solver.method fdm";
}

}  // namespace mpfd::coupler
