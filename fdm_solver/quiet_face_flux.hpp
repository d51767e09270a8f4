#pragma once
// What crosses each domain face where the adjacent cells are still in their
// initial state. The disturbed-region update never visits those cells, but
// the audit must count what flows through their faces: the pressure a still
// gas exerts on a wall, a steady stream through an open face. Since still
// cells never change, these fluxes are computed once.

#include <array>
#include <vector>

#include "common/config/scene.hpp"
#include "common/eos/any_eos.hpp"
#include "fdm_solver/euler_state.hpp"

namespace mpfd::fdm {

/// Per face (config::Face order), per variable (x/y/z order), per boundary
/// cell: the flux through the face in the +axis direction [per m^2 and s].
/// Boundary cells of face normal to axis a are numbered l1 + n[a1] l2 with
/// a1 = (a+1)%3, a2 = (a+2)%3.
struct QuietFaceFlux {
  std::array<std::array<std::vector<double>, kVariables>, 6> flux;
  std::array<std::array<double, kVariables>, 6> total{};  ///< summed over each face's cells
};

/// Wall and symmetry faces: (0, p n, 0) (a still gas has no normal velocity
/// there); outflow faces: the Euler flux of the boundary cell, T (2-50).
QuietFaceFlux quiet_face_flux(const EulerState& state, const config::Boundaries& boundaries,
                              const std::vector<eos::AnyEos>& eos);

}  // namespace mpfd::fdm
