#pragma once
// The CFDMP regions of protocol §6 (proto/README.md), computed from a scene's
// zones (T §4.2, Fig. 4.3): the MPM zone's one boundary face inside the domain
// (between cells k-w and k-w+1), the FDM zone ending w cells past it (cell k),
// and the boxes the coupler declares in Setup. Boxes are wire boxes: 3 axes,
// half-open, cells and nodes numbered on the scene's grid (node i = lower
// corner of cell i); an inactive axis is [0, 1).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/config/scene.hpp"

namespace mpfd::coupler {

using WireIndex = std::array<std::int64_t, 3>;

struct WireBox {
  WireIndex lo{};
  WireIndex hi{};
  [[nodiscard]] std::int64_t count() const {
    return (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  }
};

/// `box` with axis `a` replaced by [lo, hi).
inline WireBox along(WireBox box, int a, std::int64_t lo, std::int64_t hi) {
  box.lo[a] = lo;
  box.hi[a] = hi;
  return box;
}

/// Cell layers outside the MPM zone a crossing particle may land in (one
/// cell per step under the CFL limit, one more for safety).
inline constexpr std::int64_t kDepositLayers = 2;

struct ZoneLayout {
  int dimension = 1;          ///< active axes of the scene's grid
  std::array<int, 3> active;  ///< the active axes in order (first `dimension` entries)
  int face_axis = 0;          ///< normal of the MPM zone's coupling face
  int face_side = 1;          ///< +1: the MPM zone lies above the face along face_axis
  int handshake_width = 0;    ///< w [cells], the zones' overlap along face_axis
  WireIndex cells{};          ///< the scene's cells per axis
  WireBox fdm_zone;           ///< cells of the FDM zone
  WireBox mpm_zone;           ///< cells of the MPM zone
  WireBox fdm_owned;        ///< FDM zone cells outside the MPM zone (the FDM's share of the audit)
  WireBox ghost_cells;      ///< FDM ghost layers inside the MPM zone (cells k+1 ...)
  WireBox strip_cells;      ///< cells k-w (outside) and k-w+1 (inside) across the face
  WireBox deposit_cells;    ///< cells outside the face where crossing particles land
  WireBox ghost_nodes;      ///< corner nodes of the ghost cells
  WireBox interface_nodes;  ///< the node layer on the face
  WireBox beyond_cells;     ///< cells k-w-1 (uGIMP/cpGIMP MPM: they feed outer_nodes)
  WireBox outer_nodes;      ///< node layer one cell outside the face (uGIMP/cpGIMP MPM only)
  WireBox face_cells;       ///< the cells k-w+1: the MPM zone's cell layer on the face
  WireBox coupling_face;  ///< v1.1 FACES box: the faces at node `face` (one index along face_axis)
};

/// Computes the layout of a cfdmp scene. Throws mpfd::Error naming the rule
/// when the scene is not cfdmp, when the MPM zone has no face or more than one
/// face inside the domain (this coupler drives one face), when it does not span
/// the domain across that face, or when the FDM zone leaves no room for the
/// strip, deposit and ghost layers.
[[nodiscard]] ZoneLayout make_zone_layout(const config::Scene& scene);

/// True when the scene's MPM particles reach one node layer outside their cell
/// (uGIMP, cpGIMP): the coupler then also feeds outer_nodes from the FDM
/// (handshake::outer_node_terms). Linear shapes stop at the face node layer.
[[nodiscard]] bool mpm_reaches_outer_nodes(const config::Scene& scene);

/// Per scene material, 1 if it has a strength model (a solid): the FDM's push on
/// the face nodes counts a solid by its volume (face_push_volume), so in a scene
/// with one (config::has_structure) face_particles also carries volume and material.
[[nodiscard]] std::vector<char> material_strength_flags(const config::Scene& scene);

/// "[lo0, hi0) x [lo1, hi1) x [lo2, hi2)", for messages.
[[nodiscard]] std::string box_text(const WireBox& box);

}  // namespace mpfd::coupler
