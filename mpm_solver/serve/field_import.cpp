#include "mpm_solver/serve/field_import.hpp"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "common/core/require.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "mpm_solver/serve/particle_transfer.hpp"

namespace mpfd::mpm {
namespace {

/// What a PARTICLES field may carry into the zone: the arrays of InjectParticles.
constexpr std::array<std::string_view, 8> kImported = {
    "id", "position", "velocity", "mass", "volume", "internal_energy", "material", "stress"};

[[noreturn]] void refuse_import(cosim::v1::ErrorCode code, const std::string& what) {
  throw cosim::ProtocolError(code, "FieldImportCommit: " + what, false);
}

/// The PARTICLES regions the fields name, in first-seen order, each checked.
std::vector<const ZoneRegion*> imported_regions(const ServedZone& zone,
                                                const cosim::Message& fields) {
  std::vector<const ZoneRegion*> regions;
  for (const auto& array : fields.header.arrays()) {
    const std::string field = array.group() + "/" + array.name();
    const ZoneRegion* region = nullptr;
    try {
      region = &zone.region(array.group(), "FieldImportCommit field '" + field + "'");
    } catch (const cosim::ProtocolError& error) {
      throw cosim::ProtocolError(error.code(), error.what(), false);
    }
    if (region->kind != cosim::v1::REGION_KIND_PARTICLES)
      refuse_import(
          cosim::v1::ERROR_CODE_UNEXPECTED,
          "field '" + field +
              "': only PARTICLES regions of an MPM zone import (NODES regions export only)");
    if (std::find(kImported.begin(), kImported.end(), array.name()) == kImported.end())
      refuse_import(cosim::v1::ERROR_CODE_MALFORMED,
                    "field '" + field +
                        "': a PARTICLES import carries id, position, velocity, mass, volume, "
                        "internal_energy, material and optionally stress");
    if (!region->declares(array.name()))
      refuse_import(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                    "field '" + field + "': quantity not declared for region '" + region->name +
                        "' in Setup (proto/README.md §15 rule 1)");
    if (std::find(regions.begin(), regions.end(), region) == regions.end())
      regions.push_back(region);
  }
  return regions;
}

/// Throws MALFORMED naming the first particle of `batch` outside the region's box.
void check_inside(const ParticleBatch& batch, const ZoneRegion& region,
                  const grid::UniformGrid& grid) {
  const RegionExtent extent(region, grid);
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const double* x = &batch.position[3 * i];
    if (extent.contains(x)) continue;
    std::string box;
    for (std::size_t a = 0; a < 3; ++a)
      if (extent.active(a))
        box += std::string(box.empty() ? "" : ", ") + "axis " + std::to_string(a) + " [" +
               shortest_text(extent.lower(a)) + ", " + shortest_text(extent.upper(a)) + ")";
    refuse_import(cosim::v1::ERROR_CODE_MALFORMED,
                  "region '" + region.name + "': particle " + std::to_string(i) + " (id " +
                      std::to_string(batch.id[i]) + ") at (" + shortest_text(x[0]) + ", " +
                      shortest_text(x[1]) + ", " + shortest_text(x[2]) +
                      ") m lies outside the region's box " + box + " m");
  }
}

void append(ParticleBatch& all, const ParticleBatch& batch) {
  const auto add = [](auto& to, const auto& from) {
    to.insert(to.end(), from.begin(), from.end());
  };
  add(all.id, batch.id);
  add(all.position, batch.position);
  add(all.velocity, batch.velocity);
  add(all.mass, batch.mass);
  add(all.volume, batch.volume);
  add(all.internal_energy, batch.internal_energy);
  add(all.material, batch.material);
  add(all.stress, batch.stress);
}

/// FieldImportDone.totals of particles [first, end) as the solver holds them (§15 rule 5).
std::array<double, 5> totals_from(const ParticleSet& ps, std::size_t first) {
  std::array<double, 5> totals{};
  for (std::size_t p = first; p < ps.size(); ++p) {
    const double m = ps.mass[p];
    double v2 = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
      totals[1 + a] += m * ps.velocity[a][p];
      v2 += ps.velocity[a][p] * ps.velocity[a][p];
    }
    totals[0] += m;
    totals[4] += m * ps.specific_internal_energy[p] + 0.5 * m * v2;
  }
  return totals;
}

}  // namespace

cosim::v1::FieldChunkAck receive_field_chunk(ServedZone& zone, const cosim::Message& chunk) {
  const auto& body = chunk.header.field_chunk();
  if (!zone.field_import || zone.field_import->transfer_id() != body.transfer_id())
    zone.field_import.emplace(body.transfer_id());  // §15 rule 3: a new transfer discards the old
  try {
    zone.field_import->add(chunk);
  } catch (const Error& error) {
    zone.field_import.reset();
    throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED, error.what(), false);
  }
  cosim::v1::FieldChunkAck ack;
  ack.set_transfer_id(body.transfer_id());
  ack.set_chunk_index(body.chunk_index());
  return ack;
}

cosim::v1::FieldImportDone commit_field_import(ServedZone& zone, const cosim::Message& commit) {
  const auto& body = commit.header.field_import_commit();
  // A commit ends the import whatever its outcome: a refused one is sent again whole.
  std::optional<cosim::FieldAssembly> import = std::move(zone.field_import);
  zone.field_import.reset();
  if (body.tracers())
    refuse_import(cosim::v1::ERROR_CODE_MALFORMED,
                  "transfer '" + body.transfer_id() +
                      "' has tracers set, but an MPM zone has no TRACERS regions");
  if (!import || import->transfer_id() != body.transfer_id())
    refuse_import(
        cosim::v1::ERROR_CODE_MALFORMED,
        "no import of transfer '" + body.transfer_id() + "' was received" +
            (import ? " (the chunks received are of '" + import->transfer_id() + "')" : ""));
  if (!import->complete())
    refuse_import(cosim::v1::ERROR_CODE_MALFORMED,
                  "transfer '" + body.transfer_id() + "' is incomplete after " +
                      std::to_string(import->chunks()) + " chunks (no chunk with last = true)");
  const cosim::Message fields = import->take();

  ParticleBatch all;
  bool with_stress = false;
  const auto regions = imported_regions(zone, fields);
  for (const ZoneRegion* region : regions) {
    ParticleBatch batch;
    try {
      batch = read_particle_batch(fields, "FieldImportCommit", region->name);
    } catch (const cosim::ProtocolError& error) {
      throw cosim::ProtocolError(error.code(), error.what(), false);
    }
    const bool stressed = std::any_of(
        fields.header.arrays().begin(), fields.header.arrays().end(), [&](const auto& array) {
          return array.group() == region->name && array.name() == "stress";
        });
    if (region != regions.front() && stressed != with_stress)
      refuse_import(cosim::v1::ERROR_CODE_MALFORMED,
                    "region '" + region->name + "': stress given for some imported regions only");
    with_stress = stressed;
    check_inside(batch, *region, zone.solver.grid());
    append(all, batch);
  }
  const std::size_t first = zone.solver.particles().size();
  try {
    zone.solver.inject_particles(all);
  } catch (const Error& error) {
    refuse_import(cosim::v1::ERROR_CODE_MALFORMED, error.what());
  }
  zone.start_time = commit.header.envelope().sim_time() - zone.solver.time();
  cosim::v1::FieldImportDone done;
  done.set_transfer_id(body.transfer_id());
  done.set_stable_dt(zone.solver.stable_dt());
  for (const double total : totals_from(zone.solver.particles(), first)) done.add_totals(total);
  return done;
}

}  // namespace mpfd::mpm
