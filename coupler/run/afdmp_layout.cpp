#include "coupler/run/afdmp_layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

// A shape's bounding box within this fraction of a cell of a grid line is on it.
constexpr double kGridLineTolerance = 1e-9;

/// The cells a box [lower, upper] in m touches, clipped to the grid; an
/// inactive axis is [0, 1).
WireBox cells_touched(const config::Domain& domain, const config::Vec3& lower,
                      const config::Vec3& upper) {
  WireBox box;
  for (int a = 0; a < 3; ++a) {
    const std::int64_t n = domain.cells[a];
    if (n == 1) {
      box.lo[a] = 0;
      box.hi[a] = 1;
      continue;
    }
    const double h = (domain.upper[a] - domain.lower[a]) / static_cast<double>(n);
    const auto lo = static_cast<std::int64_t>(
        std::floor((lower[a] - domain.lower[a]) / h + kGridLineTolerance));
    const auto hi =
        static_cast<std::int64_t>(std::ceil((upper[a] - domain.lower[a]) / h - kGridLineTolerance));
    box.lo[a] = std::clamp<std::int64_t>(lo, 0, n);
    box.hi[a] = std::clamp<std::int64_t>(hi, 0, n);
  }
  return box;
}

bool contains(const WireBox& outer, const WireBox& inner) {
  for (int a = 0; a < 3; ++a)
    if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a]) return false;
  return true;
}

bool overlaps(const WireBox& x, const WireBox& y) {
  for (int a = 0; a < 3; ++a)
    if (x.hi[a] <= y.lo[a] || y.hi[a] <= x.lo[a]) return false;
  return true;
}

/// Finds the FSI zone's one inner face and the fluid and watch boxes.
void place_fsi_zone(const config::Scene& scene, AfdmpLayout& layout) {
  const std::string who = "scene '" + scene.name + "': ";
  const config::MpmZone& zone = *scene.zones->mpm;
  const WireBox fsi = cells_touched(scene.domain, zone.lower, zone.upper);
  int faces = 0;
  for (int a = 0; a < 3; ++a) {
    if (layout.cells[a] == 1) continue;
    for (const int side : {1, -1}) {
      if (!(side > 0 ? fsi.lo[a] > 0 : fsi.hi[a] < layout.cells[a])) continue;
      ++faces;
      layout.face_axis = a;
      layout.face_side = side;
    }
  }
  if (faces != 1)
    throw Error(who + "afdmp expected the FSI zone (zones.mpm) " + box_text(fsi) +
                " to have exactly one face inside the domain, found " + std::to_string(faces));
  const int a = layout.face_axis;
  for (int b = 0; b < 3; ++b)
    if (b != a && (fsi.lo[b] != 0 || fsi.hi[b] != layout.cells[b]))
      throw Error(who + "afdmp expected the FSI zone " + box_text(fsi) +
                  " to span the domain along " + config::kAxisNames[b] +
                  " (across its face normal to " + config::kAxisNames[a] + ")");
  if (!zone.activation_pressure)
    throw Error(who +
                "afdmp needs zones.mpm.activation_pressure [Pa]: the FSI zone takes over "
                "when the fluid pressure next to it reaches it (T §3.2.3)");
  const std::int64_t face = layout.face_side > 0 ? fsi.lo[a] : fsi.hi[a];
  layout.fluid_cells = layout.face_side > 0 ? along(layout.all_cells, a, 0, face)
                                            : along(layout.all_cells, a, face, layout.cells[a]);
  const std::int64_t fluid_layers = layout.fluid_cells.hi[a] - layout.fluid_cells.lo[a];
  if (fluid_layers < std::max<std::int64_t>(kWatchLayers, 2))
    throw Error(who + "afdmp expected the fluid zone " + box_text(layout.fluid_cells) +
                " to be >= " + std::to_string(std::max<std::int64_t>(kWatchLayers, 2)) +
                " cells wide along " + config::kAxisNames[a] + ", got " +
                std::to_string(fluid_layers));
  layout.watch_cells = layout.face_side > 0 ? along(layout.all_cells, a, face - kWatchLayers, face)
                                            : along(layout.all_cells, a, face, face + kWatchLayers);
  layout.fsi_cells = fsi;
  layout.activation_pressure = zone.activation_pressure;
}

bool has_strength(const config::Scene& scene, const config::Body& body) {
  const config::Material* m = config::find_material(scene, body.state.material);
  return m != nullptr && config::has_strength(*m);
}

}  // namespace

AfdmpLayout make_afdmp_layout(const config::Scene& scene) {
  const std::string who = "scene '" + scene.name + "': ";
  if (scene.solver.method != config::Method::afdmp)
    throw Error(who + "the afdmp layout needs solver.method afdmp");
  if (scene.charges.empty())
    throw Error(who + "afdmp needs at least one charge (phase 1 detonates it, T §3.2.1)");
  AfdmpLayout layout;
  layout.dimension = 0;
  for (int a = 0; a < 3; ++a) {
    layout.cells[a] = scene.domain.cells[a];
    if (scene.domain.cells[a] > 1) layout.active[layout.dimension++] = a;
  }
  layout.all_cells = WireBox{{0, 0, 0}, layout.cells};
  layout.fluid_cells = layout.all_cells;
  if (scene.zones && scene.zones->mpm) place_fsi_zone(scene, layout);

  bool first = true;
  for (const config::Charge& charge : scene.charges) {
    const config::Box bounds = config::bounding_box(charge.shape);
    const WireBox cells = cells_touched(scene.domain, bounds.lower, bounds.upper);
    if (layout.fsi_cells && overlaps(cells, *layout.fsi_cells))
      throw Error(who + "afdmp expected charge '" + charge.name + "' (cells " + box_text(cells) +
                  ") inside the fluid zone " + box_text(layout.fluid_cells) +
                  ", it reaches into the FSI zone " + box_text(*layout.fsi_cells));
    for (int a = 0; a < 3; ++a) {
      layout.charge_cells.lo[a] =
          first ? cells.lo[a] : std::min(layout.charge_cells.lo[a], cells.lo[a]);
      layout.charge_cells.hi[a] =
          first ? cells.hi[a] : std::max(layout.charge_cells.hi[a], cells.hi[a]);
    }
    first = false;
  }
  for (int a = 0; a < 3; ++a) {  // grown by one cell, within the fluid zone
    if (layout.cells[a] == 1) continue;
    layout.charge_cells.lo[a] = std::max(layout.charge_cells.lo[a] - 1, layout.fluid_cells.lo[a]);
    layout.charge_cells.hi[a] = std::min(layout.charge_cells.hi[a] + 1, layout.fluid_cells.hi[a]);
  }

  for (const config::Body& body : scene.bodies) {
    if (!has_strength(scene, body)) continue;
    const config::Box bounds = config::bounding_box(body.shape);
    const WireBox cells = cells_touched(scene.domain, bounds.lower, bounds.upper);
    if (!layout.fsi_cells)
      throw Error(who + "afdmp: body '" + body.name +
                  "' has a strength model but the scene has no FSI zone (zones.mpm); the FDM "
                  "carries no strength");
    if (!contains(*layout.fsi_cells, cells))
      throw Error(who + "afdmp expected body '" + body.name + "' (cells " + box_text(cells) +
                  "), which has a strength model, inside the FSI zone " +
                  box_text(*layout.fsi_cells) + "; the FDM carries no strength");
  }
  return layout;
}

namespace {

/// The v1.1 ledgers (proto/README.md §14) of an audit region.
void add_outflow_quantities(v1::Region& region) {
  for (const char* q : {"outflow_mass", "outflow_momentum", "outflow_energy"})
    region.add_quantities(q);
}

}  // namespace

AfdmpRegions afdmp_setup_regions(const AfdmpLayout& layout, AfdmpStart start, AuditOutflow outflow,
                                 bool material_import) {
  namespace r = afdmp_region;
  using Kind = v1::RegionKind;
  AfdmpRegions out;
  out.fdm.push_back(make_region(r::kAllCells, Kind::REGION_KIND_CELLS, layout.all_cells,
                                {"rho", "momentum", "E"}));
  if (material_import)  // each material's own start in the mixed cells of either handoff
    for (const char* q : {"volume_fraction", "material_density", "material_energy"})
      out.fdm.back().add_quantities(q);
  out.fdm.push_back(make_region(r::kAllTracers, Kind::REGION_KIND_TRACERS, layout.all_cells,
                                {"position", "material"}));
  if (layout.fsi_cells) {
    out.fdm.push_back(make_region(r::kFluidCells, Kind::REGION_KIND_CELLS, layout.fluid_cells,
                                  {"rho", "momentum", "E", "pressure", "cell_material",
                                   "volume_fraction", "material_density", "material_energy"}));
    out.fdm.push_back(make_region(r::kFluidTracers, Kind::REGION_KIND_TRACERS, layout.fluid_cells,
                                  {"position", "material"}));
    out.fdm.push_back(
        make_region(r::kFsiWatch, Kind::REGION_KIND_CELLS, *layout.watch_cells, {"pressure"}));
    out.fdm.push_back(make_region(r::kFsiCells, Kind::REGION_KIND_CELLS, *layout.fsi_cells,
                                  {"rho", "momentum", "E"}));
  }
  out.fdm.push_back(make_region(r::kAuditCells, Kind::REGION_KIND_CELLS, layout.all_cells,
                                {"rho", "momentum", "E"}));
  if (outflow.fdm) add_outflow_quantities(out.fdm.back());
  if (start == AfdmpStart::spherical && !layout.fsi_cells) return out;
  out.mpm.push_back(make_region(r::kFluidParticles, Kind::REGION_KIND_PARTICLES, layout.fluid_cells,
                                {"id", "position", "velocity", "mass", "volume", "internal_energy",
                                 "material", "stress", "burn_fraction"}));
  if (layout.fsi_cells)
    out.mpm.push_back(make_region(r::kFsiParticles, Kind::REGION_KIND_PARTICLES, *layout.fsi_cells,
                                  {"mass", "velocity", "internal_energy"}));
  if (start == AfdmpStart::mpm)
    out.mpm.push_back(make_region(r::kChargeParticles, Kind::REGION_KIND_PARTICLES,
                                  layout.charge_cells, {"burn_fraction", "material"}));
  out.mpm.push_back(make_region(r::kAuditParticles, Kind::REGION_KIND_PARTICLES, layout.all_cells,
                                {"mass", "velocity", "internal_energy"}));
  if (outflow.mpm) add_outflow_quantities(out.mpm.back());
  return out;
}

handoff::CellBox to_cell_box(const WireBox& box) {
  handoff::CellBox out;
  for (int a = 0; a < 3; ++a) {
    out.lo[a] = static_cast<int>(box.lo[a]);
    out.hi[a] = static_cast<int>(box.hi[a]);
  }
  return out;
}

}  // namespace mpfd::coupler
