#include "coupler/run/afdmp_handoffs.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "cosim/arrays.hpp"
#include "coupler/handoff/detonation_trigger.hpp"
#include "coupler/handoff/material_start.hpp"
#include "coupler/handoff/mpm_to_fdm.hpp"
#include "coupler/handoff/placeholder.hpp"
#include "coupler/handoff/sub_grid.hpp"
#include "coupler/remap/radial_tracers.hpp"
#include "coupler/remap/shell_material_sums.hpp"
#include "coupler/remap/spherical_to_cartesian.hpp"
#include "coupler/run/afdmp_fields.hpp"
#include "coupler/run/field_transfer.hpp"
#include "coupler/run/session.hpp"

namespace mpfd::coupler {
namespace {

using Clock = std::chrono::steady_clock;
namespace region = afdmp_region;

grid::UniformGrid whole_grid(const config::Scene& scene) {
  return grid::UniformGrid::from_bounds(scene.domain.lower, scene.domain.upper, scene.domain.cells);
}

/// The worst of the comparisons, by their worst component.
ConservedError worst_of(std::initializer_list<ConservedError> errors) {
  ConservedError worst;
  for (const auto& e : errors)
    if (e.worst() > worst.worst()) worst = e;
  return worst;
}

nlohmann::json transfer_json(const FieldTransferStats& stats) {
  return {{"chunks", stats.chunks}, {"bytes", stats.bytes}};
}

handoff::ConservedView remapped_view(const remap::CartesianFields& f) {
  return {f.density, {f.momentum[0], f.momentum[1], f.momentum[2]}, f.total_energy};
}

/// The 1D stage's profile on the whole grid, the scene's initial state (the
/// ambient air) filling what it does not cover, and the totals the handoff
/// checks.
struct SphericalCells {
  handoff::ConservedCells cells;  ///< remapped + fill: what the FDM imports
  Conserved remapped;             ///< of the remapped cells alone
  Conserved radial;               ///< the same with the radial impulse in momentum[0]
  Conserved fill;                 ///< of the ambient fill alone
  /// Each material's start in the cells, if asked for: the shells of each
  /// material and the fill, fitted to the cells (handoff/material_start.hpp).
  std::optional<handoff::MaterialStart> start;
};

/// The fill is added in place and only the cells are kept: the remap's
/// per-material parts and covered fractions (96 B per cell with two materials)
/// are gone before the FDM builds its state, the handoff's memory peak. With
/// `start_materials` (the FDM takes each material's start), the per-material
/// parts become the sums (+8 B per cell with two materials), and the start
/// (48 B per cell) is fitted in their place.
SphericalCells spherical_cells(const grid::UniformGrid& grid, const grid::Vec3& centre,
                               const remap::RadialProfile& profile,
                               const handoff::AmbientState& ambient,
                               std::optional<int> start_materials) {
  remap::CartesianFields f = remap::remap_radial_profile(grid, centre, profile);
  const double volume = grid.cell_volume();
  SphericalCells out;
  out.remapped = cell_conserved(remapped_view(f), volume);
  out.radial = out.remapped;
  out.radial.momentum = {0, 0, 0};
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const auto x = grid.cell_center(grid.cell_of_index(c));
    const double d[3] = {x[0] - centre[0], x[1] - centre[1], x[2] - centre[2]};
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    if (r > 0)
      for (int a = 0; a < 3; ++a) out.radial.momentum[0] += f.momentum[a][c] * d[a] / r * volume;
  }
  out.radial.momentum_scale = std::abs(out.radial.momentum[0]);
  const double ambient_e = ambient.density * (ambient.specific_internal_energy +
                                              0.5 * (ambient.velocity[0] * ambient.velocity[0] +
                                                     ambient.velocity[1] * ambient.velocity[1] +
                                                     ambient.velocity[2] * ambient.velocity[2]));
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const double rest = std::max(0.0, 1.0 - f.covered_fraction[c]);
    const double density = rest * ambient.density;
    const double energy = rest * ambient_e;
    std::array<double, 3> momentum{};
    for (int a = 0; a < 3; ++a) momentum[a] = rest * ambient.density * ambient.velocity[a];
    add_cell(out.fill, density, momentum, energy, volume);
    f.density[c] += density;
    f.total_energy[c] += energy;
    for (int a = 0; a < 3; ++a) f.momentum[a][c] += momentum[a];
  }
  out.cells.density = std::move(f.density);
  out.cells.momentum = std::move(f.momentum);
  out.cells.total_energy = std::move(f.total_energy);
  if (start_materials) {
    out.start = handoff::material_start(
        grid, remap::shell_material_sums(std::move(f), volume, ambient, *start_materials),
        out.cells.view());
  }
  return out;
}

/// Cells and tracers of the whole grid into the FDM (fields all_cells, all_tracers),
/// with each material's start in the cells if `start` is given. `cells` and
/// `start` are consumed: released once on the wire, the wire once sent, so
/// that neither is held while the FDM builds its state (the handoff's peak).
cosim::v1::FieldImportDone import_into_fdm(const grid::UniformGrid& grid,
                                           handoff::ConservedCells cells,
                                           const handoff::TracerPoints& tracers,
                                           std::optional<handoff::MaterialStart> start,
                                           std::string_view transfer, cosim::Hub& hub,
                                           const HandoffSettings& settings,
                                           FieldTransferStats& stats) {
  cosim::Message fields;
  add_cells_to_wire(grid, cells.view(), region::kAllCells, fields);
  cells = {};
  add_tracers_to_wire(tracers.view(), region::kAllTracers, fields);
  auto names = field_names(region::kAllCells, {"rho", "momentum", "E"});
  if (start) {
    add_material_start_to_wire(grid, *start, region::kAllCells, fields);
    start.reset();
    for (auto& name :
         field_names(region::kAllCells, {"volume_fraction", "material_density", "material_energy"}))
      names.push_back(std::move(name));
  }
  for (auto& name : field_names(region::kAllTracers, {"position", "material"}))
    names.push_back(std::move(name));
  return import_fields(hub, "fdm", transfer, std::move(fields), names, settings.max_chunk_bytes,
                       true, settings.timeout, &stats);
}

/// The fluid box's material start in the whole grid; the other cells have none.
handoff::MaterialStart embed_start(const grid::UniformGrid& grid, const handoff::CellBox& box,
                                   handoff::MaterialStart start) {
  const std::size_t rows = grid.cell_count() * static_cast<std::size_t>(start.material_count);
  for (auto* values : {&start.volume_fraction, &start.density, &start.energy}) {
    std::vector<double> whole(rows, 0.0);
    handoff::embed_cells(grid, box, *values, whole, start.material_count);
    *values = std::move(whole);
  }
  return start;
}

nlohmann::json start_json(const handoff::MaterialStart* start, const char* why_not) {
  if (start == nullptr) return {{"sent", false}, {"why", why_not}};
  return {{"sent", true},
          {"mixed_cells", start->mixed_cells},
          {"fallback_cells", start->fallback_cells},
          {"cells_without_state", start->empty_cells}};
}

}  // namespace

std::vector<int> explosive_materials(const config::Scene& scene) {
  std::vector<int> out;
  for (const auto& charge : scene.charges)
    for (std::size_t m = 0; m < scene.materials.size(); ++m)
      if (scene.materials[m].name == charge.material) out.push_back(static_cast<int>(m));
  return out;
}

double handoff_tolerance(std::size_t values) {
  return std::max(1e-12,
                  2.0 * static_cast<double>(values) * std::numeric_limits<double>::epsilon());
}

Conserved placeholder_conserved(const config::Scene& scene, const AfdmpLayout& layout) {
  if (!layout.fsi_cells) return {};
  const grid::UniformGrid grid = whole_grid(scene);
  handoff::ConservedCells cells;
  cells.assign(grid.cell_count());
  handoff::fill_ambient_cells(grid, to_cell_box(*layout.fsi_cells), handoff::ambient_state(scene),
                              cells);
  return cell_conserved(cells.view(), grid.cell_volume());
}

HandoffRecord handoff_mpm_to_fdm(const config::Scene& scene, const AfdmpLayout& layout,
                                 cosim::Hub& hub, const HandoffSettings& settings) {
  const auto start = Clock::now();
  FieldTransferStats exported, imported;
  auto names =
      field_names(region::kFluidParticles,
                  {"position", "velocity", "mass", "internal_energy", "material", "burn_fraction"});
  if (settings.material_import) names.push_back(std::string(region::kFluidParticles) + "/volume");
  cosim::Message fields = export_fields(hub, "mpm", "mpm_to_fdm", names, settings.max_chunk_bytes,
                                        settings.timeout, &exported);
  const handoff::ParticleSet particles = particles_from_wire(fields, region::kFluidParticles);
  // Asked for: without it every mixed cell would fall back to the cell's state unnoticed.
  if (settings.material_import)
    static_cast<void>(cosim::view_array<double>(fields, region::kFluidParticles, "volume"));
  const auto burn = cosim::view_array<double>(fields, region::kFluidParticles, "burn_fraction");
  const auto explosive = explosive_materials(scene);
  if (!handoff::detonation_complete(burn.values(), particles.material, explosive)) {
    std::size_t p = 0;
    while (p < particles.size() &&
           (burn.values()[p] >= 1.0 || std::find(explosive.begin(), explosive.end(),
                                                 particles.material[p]) == explosive.end()))
      ++p;
    throw Error(
        "AFDMP: the MPM -> FDM handoff found an unburnt explosive particle in "
        "fluid_particles: number " +
        std::to_string(p) + " at (" + std::to_string(particles.position[0][p]) + ", " +
        std::to_string(particles.position[1][p]) + ", " + std::to_string(particles.position[2][p]) +
        ") m, material " + std::to_string(particles.material[p]) +
        ", F = " + std::to_string(burn.values()[p]) + "; expected F >= 1 for every one (T §3.2.1)");
  }
  fields = cosim::Message{};  // read: not held while the FDM builds its state

  const grid::UniformGrid grid = whole_grid(scene);
  const handoff::CellBox fluid_box = to_cell_box(layout.fluid_cells);
  const grid::UniformGrid fluid_grid = handoff::sub_grid(grid, fluid_box);
  handoff::FdmStart fdm = handoff::mpm_to_fdm(fluid_grid, particles.view());
  std::optional<handoff::MaterialStart> material;
  if (settings.material_import)
    material = embed_start(
        grid, fluid_box,
        handoff::material_start(fluid_grid, particles.view(), particles.volume, fdm.cells.view(),
                                static_cast<int>(scene.materials.size())));
  handoff::ConservedCells cells;
  cells.assign(grid.cell_count());
  handoff::embed_cells(grid, fluid_box, fdm.cells.view(), cells);
  if (layout.fsi_cells) {
    const handoff::CellBox fsi_box = to_cell_box(*layout.fsi_cells);
    const auto ambient = handoff::ambient_state(scene);
    handoff::fill_ambient_cells(grid, fsi_box, ambient, cells);
    handoff::append_regular_tracers(grid, fsi_box, ambient.material,
                                    scene.solver.fdm.tracers_per_axis, fdm.tracers);
  }
  // What the FDM should hold: the fluid cells sent plus the FSI placeholder.
  const Conserved whole = cell_conserved(cells.view(), grid.cell_volume());
  const nlohmann::json material_json = start_json(
      material ? &*material : nullptr, "the FDM lacks material_import: the cells' state");
  const auto done = import_into_fdm(grid, std::move(cells), fdm.tracers, std::move(material),
                                    "mpm_to_fdm", hub, settings, imported);

  const Conserved received = particle_conserved(particles.view());
  const Conserved sent = cell_conserved(fdm.cells.view(), fluid_grid.cell_volume());
  const Conserved held =
      from_totals(std::span<const double>(done.totals().data(), done.totals().size()));
  const ConservedError kernel = relative_error(received, sent);
  const Conserved placeholder = difference(whole, sent);
  const ConservedError solver = relative_error(whole, held);
  HandoffRecord record;
  record.worst_error = worst_of({kernel, solver});
  record.tolerance = handoff_tolerance(std::max(particles.size(), grid.cell_count()));
  record.stable_dt = done.stable_dt();
  record.summary = {
      {"name", "mpm_to_fdm"},
      {"particles", particles.size()},
      {"tracers", fdm.tracers.size()},
      {"cells", grid.cell_count()},
      {"received", received.summary()},
      {"sent", sent.summary()},
      {"placeholder", placeholder.summary()},
      {"solver_totals", held.summary()},
      {"relative_error",
       {{"sent_vs_received", kernel.summary()}, {"solver_vs_sent", solver.summary()}}},
      {"kinetic_to_internal_J", fdm.kinetic_to_internal},
      {"material_start", material_json},
      {"export", transfer_json(exported)},
      {"import", transfer_json(imported)},
      {"wall_s", seconds_since(start)}};
  return record;
}

HandoffRecord handoff_spherical_to_fdm(const config::Scene& scene, const SphericalStage& stage,
                                       cosim::Hub& hub, const HandoffSettings& settings) {
  const auto start = Clock::now();
  FieldTransferStats imported;
  const grid::UniformGrid grid = whole_grid(scene);
  const remap::RadialShells shells = stage.shells();
  const remap::RadialProfile profile = shells.view();
  const auto ambient = handoff::ambient_state(scene);
  // settings.material_import holds only if the scene asked for the start (it costs
  // memory at the handoff, and the far field does not see it: docs/afdmp.md). The FDM
  // takes a start row only where its tracers make a cell mixed; one tracer per cell
  // (the radial tracers at sub-cell centres) makes none.
  const bool with_start = settings.material_import && scene.solver.fdm.tracers_per_axis > 1;
  SphericalCells remapped = spherical_cells(
      grid, stage.centre(), profile, ambient,
      with_start ? std::optional<int>(static_cast<int>(scene.materials.size())) : std::nullopt);
  const handoff::TracerPoints tracers = remap::radial_tracers(
      grid, stage.centre(), profile, ambient.material, scene.solver.fdm.tracers_per_axis);
  const nlohmann::json material_json =
      start_json(remapped.start ? &*remapped.start : nullptr,
                 !scene.solver.afdmp.spherical.material_start
                     ? "solver.afdmp.spherical.material_start is off: the cells' state"
                 : !settings.material_import
                     ? "the FDM lacks material_import: the cells' state"
                     : "one tracer per cell: the FDM makes no cell mixed, the cells' state");
  const auto done =
      import_into_fdm(grid, std::move(remapped.cells), tracers, std::move(remapped.start),
                      "spherical_to_fdm", hub, settings, imported);

  // The remap conserves mass, energy and the radial impulse of the part of the
  // profile inside the grid (its vector momentum cancels by symmetry).
  const auto inside = remap::totals_inside_grid(grid, stage.centre(), profile);
  Conserved received;
  received.mass = inside.mass;
  received.energy = inside.energy;
  received.momentum[0] = inside.radial_impulse;
  received.momentum_scale = std::abs(inside.radial_impulse);
  const Conserved& sent = remapped.radial;
  const Conserved& ambient_fill = remapped.fill;
  const Conserved held =
      from_totals(std::span<const double>(done.totals().data(), done.totals().size()));
  const Conserved sent_with_fill = sum(remapped.remapped, ambient_fill);
  const ConservedError solver = relative_error(sent_with_fill, held);
  const ConservedError kernel = relative_error(received, sent);
  const auto stage_totals = stage.totals();
  HandoffRecord record;
  record.worst_error = worst_of({kernel, solver});
  record.tolerance = handoff_tolerance(grid.cell_count());
  record.stable_dt = done.stable_dt();
  record.summary = {
      {"name", "spherical_to_fdm"},
      {"stage_particles", shells.density.size()},
      {"tracers", tracers.size()},
      {"cells", grid.cell_count()},
      {"received_inside_grid", received.summary()},
      {"sent", sent.summary()},
      {"ambient_fill", ambient_fill.summary()},
      {"solver_totals", held.summary()},
      {"relative_error",
       {{"sent_vs_received", kernel.summary()}, {"solver_vs_sent", solver.summary()}}},
      {"stage_totals",
       {{"mass", stage_totals.mass},
        {"kinetic_energy", stage_totals.kinetic_energy},
        {"internal_energy", stage_totals.internal_energy}}},
      {"material_start", material_json},
      {"import", transfer_json(imported)},
      {"wall_s", seconds_since(start)}};
  return record;
}

HandoffRecord handoff_fdm_to_mpm(const config::Scene& scene, const AfdmpLayout& layout,
                                 cosim::Hub& hub, const HandoffSettings& settings,
                                 const Conserved& placeholder) {
  const auto start = Clock::now();
  FieldTransferStats exported, imported;
  auto names =
      field_names(region::kFluidCells, {"rho", "momentum", "E", "pressure", "cell_material",
                                        "volume_fraction", "material_density", "material_energy"});
  for (auto& name : field_names(region::kFluidTracers, {"position", "material"}))
    names.push_back(std::move(name));
  for (auto& name : field_names(region::kFsiCells, {"rho", "momentum", "E"}))
    names.push_back(std::move(name));
  const cosim::Message fields = export_fields(
      hub, "fdm", "fdm_to_mpm", names, settings.max_chunk_bytes, settings.timeout, &exported);

  const grid::UniformGrid grid = whole_grid(scene);
  const grid::UniformGrid fluid_grid = handoff::sub_grid(grid, to_cell_box(layout.fluid_cells));
  const FdmEndFields end(fluid_grid, fields, region::kFluidCells, region::kFluidTracers);
  const handoff::ParticleSet particles = handoff::fdm_to_mpm(fluid_grid, end.view());
  cosim::Message batch;
  add_particles_to_wire(particles, kHandoffFirstId, region::kFluidParticles, batch);
  const auto particle_names = field_names(
      region::kFluidParticles,
      {"id", "position", "velocity", "mass", "volume", "internal_energy", "material", "stress"});
  const auto done = import_fields(hub, "mpm", "fdm_to_mpm", std::move(batch), particle_names,
                                  settings.max_chunk_bytes, false, settings.timeout, &imported);

  const double volume = grid.cell_volume();
  const Conserved received = cell_conserved(end.cells().view(), volume);
  const Conserved sent = particle_conserved(particles.view());
  const Conserved held =
      from_totals(std::span<const double>(done.totals().data(), done.totals().size()));
  const auto rho = cosim::view_array<double>(fields, region::kFsiCells, "rho");
  const auto momentum = cosim::view_array<double>(fields, region::kFsiCells, "momentum");
  const auto energy = cosim::view_array<double>(fields, region::kFsiCells, "E");
  const Conserved fsi_now =
      wire_cell_conserved(rho.values(), momentum.values(), energy.values(), volume);
  const Conserved leak = difference(fsi_now, placeholder);
  const ConservedError kernel = relative_error(received, sent);
  const ConservedError solver = relative_error(sent, held);
  HandoffRecord record;
  record.worst_error = worst_of({kernel, solver});
  record.tolerance = handoff_tolerance(std::max(particles.size(), fluid_grid.cell_count()));
  record.stable_dt = done.stable_dt();
  record.fsi_face_leak = leak;
  record.summary = {
      {"name", "fdm_to_mpm"},
      {"cells", fluid_grid.cell_count()},
      {"particles", particles.size()},
      {"received", received.summary()},
      {"sent", sent.summary()},
      {"solver_totals", held.summary()},
      {"relative_error",
       {{"sent_vs_received", kernel.summary()}, {"solver_vs_sent", solver.summary()}}},
      {"fsi_face_leak", leak.summary()},
      {"export", transfer_json(exported)},
      {"import", transfer_json(imported)},
      {"wall_s", seconds_since(start)}};
  return record;
}

}  // namespace mpfd::coupler
