#include "coupler/run/zone_layout.hpp"

#include <cmath>

#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

WireBox to_cells(const config::Domain& domain, const config::Vec3& lower,
                 const config::Vec3& upper) {
  WireBox box;
  for (int a = 0; a < 3; ++a) {
    const double h = (domain.upper[a] - domain.lower[a]) / domain.cells[a];
    box.lo[a] = std::llround((lower[a] - domain.lower[a]) / h);
    box.hi[a] = std::llround((upper[a] - domain.lower[a]) / h);
  }
  return box;
}

/// Nodes of a cell box: one more on each active axis.
WireBox nodes_of(WireBox cells, const WireIndex& grid_cells) {
  for (int a = 0; a < 3; ++a)
    if (grid_cells[a] > 1) ++cells.hi[a];
  return cells;
}

}  // namespace

bool mpm_reaches_outer_nodes(const config::Scene& scene) {
  return scene.solver.mpm.shape_function != config::ShapeFunction::linear;
}

std::vector<char> material_strength_flags(const config::Scene& scene) {
  std::vector<char> flags;
  for (const auto& material : scene.materials) flags.push_back(config::has_strength(material));
  return flags;
}

std::string box_text(const WireBox& box) {
  std::string text;
  for (int a = 0; a < 3; ++a)
    text += (a ? " x [" : "[") + std::to_string(box.lo[a]) + ", " + std::to_string(box.hi[a]) + ")";
  return text;
}

ZoneLayout make_zone_layout(const config::Scene& scene) {
  const std::string who = "scene '" + scene.name + "': ";
  if (scene.solver.method != config::Method::cfdmp || !scene.zones || !scene.zones->fdm ||
      !scene.zones->mpm)
    throw Error(who + "the CFDMP coupler needs solver.method cfdmp with zones.fdm and zones.mpm");
  ZoneLayout layout;
  layout.handshake_width = scene.zones->handshake_width;
  layout.dimension = 0;
  for (int a = 0; a < 3; ++a) {
    layout.cells[a] = scene.domain.cells[a];
    if (scene.domain.cells[a] > 1) layout.active[layout.dimension++] = a;
  }
  layout.fdm_zone = to_cells(scene.domain, scene.zones->fdm->lower, scene.zones->fdm->upper);
  layout.mpm_zone = to_cells(scene.domain, scene.zones->mpm->lower, scene.zones->mpm->upper);
  const WireBox& fdm = layout.fdm_zone;
  const WireBox& mpm = layout.mpm_zone;

  int faces = 0;
  for (int a = 0; a < 3; ++a) {
    if (layout.cells[a] == 1) continue;
    for (const int side : {1, -1}) {
      const bool inside = side > 0 ? mpm.lo[a] > 0 : mpm.hi[a] < layout.cells[a];
      if (!inside) continue;
      ++faces;
      layout.face_axis = a;
      layout.face_side = side;
    }
  }
  if (faces != 1)
    throw Error(who + "expected the MPM zone " + box_text(mpm) +
                " to have exactly one face inside the domain (the coupling face), found " +
                std::to_string(faces));
  const int a = layout.face_axis;
  for (int b = 0; b < 3; ++b) {
    if (b == a || (mpm.lo[b] == 0 && mpm.hi[b] == layout.cells[b] && fdm.lo[b] == 0 &&
                   fdm.hi[b] == layout.cells[b]))
      continue;
    throw Error(who + "expected both zones to span the domain along " + config::kAxisNames[b] +
                " (across the coupling face normal to " + config::kAxisNames[a] + "), got FDM " +
                box_text(fdm) + " and MPM " + box_text(mpm));
  }

  const WireBox whole{{0, 0, 0}, layout.cells};
  const std::int64_t n = layout.cells[a];
  std::int64_t face = 0;     // node index of the coupling face
  std::int64_t fdm_end = 0;  // first cell past the FDM zone, towards the MPM zone
  if (layout.face_side > 0) {
    face = mpm.lo[a];
    fdm_end = fdm.hi[a];
    layout.strip_cells = along(whole, a, face - 1, face + 1);
    layout.deposit_cells = along(whole, a, face - kDepositLayers, face);
    layout.ghost_cells = along(whole, a, fdm_end, fdm_end + config::kFdmGhostLayers);
    layout.fdm_owned = along(whole, a, fdm.lo[a], face);
  } else {
    face = mpm.hi[a];
    fdm_end = fdm.lo[a];
    layout.strip_cells = along(whole, a, face - 1, face + 1);
    layout.deposit_cells = along(whole, a, face, face + kDepositLayers);
    layout.ghost_cells = along(whole, a, fdm_end - config::kFdmGhostLayers, fdm_end);
    layout.fdm_owned = along(whole, a, face, fdm.hi[a]);
  }
  const std::int64_t overlap = layout.face_side > 0 ? fdm_end - face : face - fdm_end;
  if (overlap < layout.handshake_width || overlap < 1)
    throw Error(who + "expected the FDM zone to reach " + std::to_string(layout.handshake_width) +
                " cells into the MPM zone along " + config::kAxisNames[a] + ", got " +
                std::to_string(overlap));
  if (layout.deposit_cells.lo[a] < fdm.lo[a] || layout.deposit_cells.hi[a] > fdm.hi[a])
    throw Error(who + "expected the FDM zone to hold " + std::to_string(kDepositLayers) +
                " cells outside the MPM zone's face at " + config::kAxisNames[a] + " cell " +
                std::to_string(face) + ", got FDM " + box_text(fdm));
  if (layout.ghost_cells.lo[a] < 0 || layout.ghost_cells.hi[a] > n ||
      layout.ghost_cells.lo[a] < mpm.lo[a] || layout.ghost_cells.hi[a] > mpm.hi[a])
    throw Error(who + "expected " + std::to_string(config::kFdmGhostLayers) +
                " FDM ghost layers inside the MPM zone past the FDM zone's end at " +
                config::kAxisNames[a] + " cell " + std::to_string(fdm_end) + ", got MPM " +
                box_text(mpm) + " in a grid of " + std::to_string(n) + " cells");
  layout.ghost_nodes = nodes_of(layout.ghost_cells, layout.cells);
  layout.interface_nodes = along(nodes_of(whole, layout.cells), a, face, face + 1);
  const std::int64_t outer = face - layout.face_side;
  layout.outer_nodes = along(nodes_of(whole, layout.cells), a, outer, outer + 1);
  layout.beyond_cells = layout.face_side > 0 ? along(whole, a, face - 2, face - 1)
                                             : along(whole, a, face + 1, face + 2);
  layout.face_cells =
      layout.face_side > 0 ? along(whole, a, face, face + 1) : along(whole, a, face - 1, face);
  layout.coupling_face = along(whole, a, face, face + 1);
  return layout;
}

}  // namespace mpfd::coupler
