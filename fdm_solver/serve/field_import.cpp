#include "fdm_solver/serve/field_import.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/active_box.hpp"
#include "fdm_solver/serve/material_quantities.hpp"

namespace mpfd::fdm {
namespace {

/// The owner of a MaterialStartView.
struct ImportedMaterialStart {
  std::vector<double> volume_fraction, density, energy;
  [[nodiscard]] MaterialStartView view() const { return {volume_fraction, density, energy}; }
};

[[noreturn]] void malformed(const std::string& transfer, const std::string& text) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                             "FieldImportCommit '" + transfer + "': " + text, false);
}

std::uint64_t value_count(const cosim::v1::ArrayDescriptor& array) {
  std::uint64_t count = 1;
  for (const auto extent : array.shape()) count *= extent;
  return count;
}

std::string field_name(const cosim::v1::ArrayDescriptor& array) {
  return array.group() + "/" + array.name();
}

/// The conserved fields of the whole grid from the CELLS arrays, in grid order.
EulerState imported_cells(const ServedZone& zone, const cosim::Message& fields,
                          const CellRegion& region, const std::string& transfer) {
  const EulerState& now = zone.solver.state();
  if (region.box.cells() != static_cast<long long>(now.grid.cell_count()))
    malformed(transfer, "region '" + region.name +
                            "' must cover the whole grid; a CELLS import sets every cell");
  EulerState cells(now.grid);  // every cell is set below: the region covers the grid
  for (const Quantity q : {Quantity::rho, Quantity::momentum, Quantity::energy}) {
    const std::string name = std::string(info(q).name);
    const cosim::v1::ArrayDescriptor* array = nullptr;
    for (const auto& a : fields.header.arrays())
      if (a.group() == region.name && a.name() == name) array = &a;
    if (array == nullptr)
      malformed(transfer, "field '" + region.name + "/" + name +
                              "' is missing; a CELLS import carries rho, momentum and E");
    const std::size_t components = info(q).components;
    if (array->dtype() != cosim::v1::DTYPE_F64 ||
        value_count(*array) != region.cell_count() * components)
      malformed(transfer, "field '" + field_name(*array) + "' must be F64 with " +
                              std::to_string(region.cell_count()) + " x " +
                              std::to_string(components) + " values, got " +
                              cosim::v1::DType_Name(array->dtype()) + " with " +
                              std::to_string(value_count(*array)));
    const cosim::ArrayView<double> view(*array, fields.frames.at(array->frame_index()));
    const auto values = view.values();
    for (std::size_t c = 0; c < components; ++c) {
      auto& target = conserved_array(cells, q, c);
      for_each_transfer_cell(now.grid, region.box, [&](std::size_t n, std::size_t cell) {
        target[cell] = values[n * components + c];
      });
    }
  }
  for (std::size_t cell = 0; cell < now.grid.cell_count(); ++cell) {
    bool finite = cells.u[kDensity][cell] > 0.0;
    for (const auto& v : cells.u) finite = finite && std::isfinite(v[cell]);
    if (!finite)
      malformed(transfer, "cell " + std::to_string(cell) + " (grid order) of region '" +
                              region.name + "' has density " +
                              std::to_string(cells.u[kDensity][cell]) +
                              " kg/m^3 or a non-finite value; densities must be positive");
  }
  return cells;
}

/// The per-material start of a CELLS import (volume_fraction, material_density,
/// material_energy, F64 [n, materials], all three or none) in the tracker's
/// layout [r * cells + cell]; empty if the import carries none of them.
ImportedMaterialStart imported_material_start(const ServedZone& zone, const cosim::Message& fields,
                                              const CellRegion& region,
                                              const std::string& transfer) {
  constexpr std::array<MaterialQuantity, 3> kStart{MaterialQuantity::volume_fraction,
                                                   MaterialQuantity::material_density,
                                                   MaterialQuantity::material_energy};
  std::array<const cosim::v1::ArrayDescriptor*, 3> arrays{};
  for (const auto& a : fields.header.arrays())
    for (std::size_t q = 0; q < kStart.size(); ++q)
      if (a.group() == region.name && a.name() == material_quantity_name(kStart[q])) arrays[q] = &a;
  const auto given = std::count_if(arrays.begin(), arrays.end(), [](auto* a) { return a; });
  ImportedMaterialStart out;
  if (given == 0) return out;
  if (given != 3)
    malformed(transfer, "region '" + region.name +
                            "' carries some of volume_fraction, material_density and "
                            "material_energy; a material start needs all three");
  const grid::UniformGrid& grid = zone.solver.state().grid;
  const std::size_t cells = grid.cell_count();
  const std::size_t materials = zone.solver.materials().size();
  std::array<std::vector<double>*, 3> targets{&out.volume_fraction, &out.density, &out.energy};
  for (std::size_t q = 0; q < kStart.size(); ++q) {
    const cosim::v1::ArrayDescriptor& array = *arrays[q];
    if (array.dtype() != cosim::v1::DTYPE_F64 ||
        value_count(array) != region.cell_count() * materials)
      malformed(transfer, "field '" + field_name(array) + "' must be F64 with " +
                              std::to_string(region.cell_count()) + " x " +
                              std::to_string(materials) + " values (cells x materials), got " +
                              cosim::v1::DType_Name(array.dtype()) + " with " +
                              std::to_string(value_count(array)));
    const cosim::ArrayView<double> view(array, fields.frames.at(array.frame_index()));
    const auto values = view.values();
    std::vector<double>& target = *targets[q];
    target.assign(materials * cells, 0.0);
    for_each_transfer_cell(grid, region.box, [&](std::size_t n, std::size_t cell) {
      for (std::size_t r = 0; r < materials; ++r) {
        const double v = values[n * materials + r];
        if (!std::isfinite(v) || v < 0.0)
          malformed(transfer, "field '" + field_name(array) + "' has " + std::to_string(v) +
                                  " for material " + std::to_string(r) + " of cell " +
                                  std::to_string(cell) +
                                  " (grid order); values must be finite "
                                  "and >= 0");
        target[r * cells + cell] = v;
      }
    });
  }
  return out;
}

/// Appends the tracers of a TRACERS region's position and material fields to `out`.
void add_imported_tracers(const ServedZone& zone, const cosim::Message& fields,
                          const TracerRegion& region, const std::string& transfer, TracerSet& out) {
  const cosim::v1::ArrayDescriptor* position = nullptr;
  const cosim::v1::ArrayDescriptor* material = nullptr;
  for (const auto& a : fields.header.arrays()) {
    if (a.group() != region.name) continue;
    if (a.name() == "position") position = &a;
    if (a.name() == "material") material = &a;
  }
  if (position == nullptr || material == nullptr)
    malformed(transfer, "TRACERS region '" + region.name + "' needs both '" + region.name +
                            "/position' and '" + region.name + "/material'");
  const std::uint64_t n = material->shape().empty() ? 0 : material->shape(0);
  if (position->dtype() != cosim::v1::DTYPE_F64 || position->shape_size() != 2 ||
      position->shape(1) != 3 || position->shape(0) != n ||
      material->dtype() != cosim::v1::DTYPE_U32 || material->shape_size() != 1)
    malformed(transfer, "region '" + region.name +
                            "': position must be F64 [n, 3] and material U32 [n] of the same n");
  const cosim::ArrayView<double> x(*position, fields.frames.at(position->frame_index()));
  const cosim::ArrayView<std::uint32_t> m(*material, fields.frames.at(material->frame_index()));
  const grid::UniformGrid& grid = zone.solver.state().grid;
  const std::size_t materials = zone.solver.materials().size();
  const grid::Vec3 lo = grid.origin();
  const grid::Vec3 hi = grid.upper();
  for (std::size_t t = 0; t < n; ++t) {
    const grid::Vec3 p{x.values()[3 * t], x.values()[3 * t + 1], x.values()[3 * t + 2]};
    bool inside = true;
    for (int a = 0; a < 3; ++a) inside = inside && p[a] >= lo[a] && p[a] <= hi[a];
    if (!inside || !region.holds(grid, p))
      malformed(transfer, "tracer " + std::to_string(t) + " of region '" + region.name + "' at (" +
                              std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                              std::to_string(p[2]) + ") m lies outside its box");
    if (m.values()[t] >= materials)
      malformed(transfer, "tracer " + std::to_string(t) + " of region '" + region.name +
                              "' has material " + std::to_string(m.values()[t]) +
                              "; the scene has " + std::to_string(materials));
    out.add(p, static_cast<int>(m.values()[t]), 0.0);
  }
}

/// What a commit imports, read out of the assembled fields.
struct ImportedFields {
  EulerState cells;
  ImportedMaterialStart start;
  std::optional<TracerSet> tracers;
};

/// Checks the assembled `fields` of a commit (`with_tracers`: its tracers
/// flag) and reads them out; the fields are released on return, before the
/// solver builds its new state from what they held.
ImportedFields read_import(const ServedZone& zone, cosim::Message fields,
                           const std::string& transfer, bool with_tracers) {
  const CellRegion* cells_region = nullptr;
  std::vector<const TracerRegion*> tracer_regions;
  for (const auto& array : fields.header.arrays()) {
    if (const TracerRegion* tracers = zone.tracer_region(array.group())) {
      if (std::find(tracer_regions.begin(), tracer_regions.end(), tracers) == tracer_regions.end())
        tracer_regions.push_back(tracers);
      continue;
    }
    if (!zone.regions.contains(array.group()))
      zone.unknown_region(array.group(), "FieldImportCommit '" + transfer + "'", false);
    const CellRegion& region = zone.region(array.group(), "FieldImportCommit");
    const auto q = find_quantity(array.name());
    const auto m = find_material_quantity(array.name());
    const bool start = m && *m != MaterialQuantity::cell_material;
    if ((!q || !info(*q).writable) && !start)
      malformed(transfer, "field '" + field_name(array) +
                              "' cannot be imported; a CELLS region imports rho, momentum and E "
                              "(and volume_fraction, material_density, material_energy)");
    if (q ? !region.declares(*q) : !region.declares(*m))
      throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                                 "FieldImportCommit '" + transfer + "': field '" +
                                     field_name(array) + "' is not declared for region '" +
                                     region.name + "' in Setup",
                                 false);
    if (cells_region != nullptr && cells_region != &region)
      malformed(transfer, "fields of two CELLS regions, '" + cells_region->name + "' and '" +
                              region.name + "'; a CELLS import sets the whole grid once");
    cells_region = &region;
  }
  if (cells_region == nullptr)
    malformed(transfer, "carries no CELLS field; an import sets rho, momentum and E of the grid");
  if (with_tracers != !tracer_regions.empty())
    malformed(transfer, std::string("tracers is ") + (with_tracers ? "true" : "false") +
                            " but the import carries " + (tracer_regions.empty() ? "no" : "a") +
                            " TRACERS field");
  ImportedFields in{imported_cells(zone, fields, *cells_region, transfer),
                    imported_material_start(zone, fields, *cells_region, transfer), std::nullopt};
  if (!tracer_regions.empty()) {
    // The tracers outside every imported box stay; those inside are replaced.
    // A box of the whole grid replaces them all: they are not read, so a
    // tracker whose seeding is pending stays unseeded (multi_material_tracker.hpp).
    in.tracers.emplace();
    const grid::UniformGrid& grid = zone.solver.state().grid;
    const ActiveBox all = whole_grid(grid);
    const bool replaces_all =
        std::any_of(tracer_regions.begin(), tracer_regions.end(), [&](const TracerRegion* r) {
          return r->box.lower == all.lower && r->box.upper == all.upper;
        });
    const MultiMaterialTracker* tracker = replaces_all ? nullptr : zone.solver.tracker();
    if (tracker != nullptr) {
      const TracerSet& kept = tracker->tracers();
      for (std::size_t t = 0; t < kept.size(); ++t) {
        const grid::Vec3 p{kept.position[0][t], kept.position[1][t], kept.position[2][t]};
        const bool replaced = std::any_of(tracer_regions.begin(), tracer_regions.end(),
                                          [&](const TracerRegion* r) { return r->holds(grid, p); });
        if (!replaced) in.tracers->add(p, kept.material[t], 0.0);
      }
    }
    for (const TracerRegion* region : tracer_regions)
      add_imported_tracers(zone, fields, *region, transfer, *in.tracers);
  }
  return in;
}

}  // namespace

cosim::Message add_import_chunk(ServedZone& zone, const cosim::Message& chunk) {
  const auto& body = chunk.header.field_chunk();
  if (!zone.pending_import || zone.pending_import->transfer_id() != body.transfer_id())
    zone.pending_import.emplace(body.transfer_id());  // a new transfer drops an unfinished one
  try {
    zone.pending_import->add(chunk);
  } catch (const cosim::ProtocolError&) {
    zone.pending_import.reset();
    throw;
  } catch (const std::exception& error) {  // a frame the chunk's descriptor does not match
    zone.pending_import.reset();
    throw cosim::ProtocolError(
        cosim::v1::ERROR_CODE_MALFORMED,
        "FieldChunk " + std::to_string(body.chunk_index()) + ": " + error.what(), false);
  }
  cosim::Message ack;
  ack.header.mutable_field_chunk_ack()->set_transfer_id(body.transfer_id());
  ack.header.mutable_field_chunk_ack()->set_chunk_index(body.chunk_index());
  return ack;
}

cosim::Message commit_import(ServedZone& zone, const cosim::Message& commit) {
  const auto& body = commit.header.field_import_commit();
  const std::string& transfer = body.transfer_id();
  if (!zone.pending_import || zone.pending_import->transfer_id() != transfer)
    malformed(transfer, "no FieldChunk of this transfer arrived");
  std::optional<cosim::FieldAssembly> pending;
  pending.swap(zone.pending_import);  // consumed, whatever the outcome
  ImportedFields in = read_import(zone, pending->take(), transfer, body.tracers());
  const double sim_time = commit.header.envelope().sim_time();
  if (!std::isfinite(sim_time))
    malformed(transfer, "the commit's envelope sim_time must be finite; it becomes the clock");
  try {
    zone.solver.import_state(std::move(in.cells), std::move(in.tracers), in.start.view());
  } catch (const Error& error) {  // import_state changes nothing when it throws
    malformed(transfer, error.what());
  }
  zone.start_time = sim_time - zone.solver.time();  // README §15 rule 4
  cosim::Message done;
  auto& reply = *done.header.mutable_field_import_done();
  reply.set_transfer_id(transfer);
  reply.set_stable_dt(zone.solver.stable_dt());
  for (const double total : zone.solver.totals()) reply.add_totals(total);  // the whole grid
  return done;
}

}  // namespace mpfd::fdm
