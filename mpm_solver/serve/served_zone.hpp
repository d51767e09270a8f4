#pragma once
// The MPM zone a coupler set up (proto/README.md §5 Setup): the scene, the
// solver built from it, the named node and particle regions, the snapshot
// writer, the particles that following gauges read, and whether the zone still sleeps (Zone.dormant
// until Activate).

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "common/config/scene.hpp"
#include "common/io/snapshot_writer.hpp"
#include "cosim/message.hpp"
#include "cosim/serving/field_stream.hpp"
#include "mpm_solver/followed_gauges.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "mpm_solver/serve/particle_transfer.hpp"
#include "mpm_solver/serve/zone_region.hpp"
#include "mpm_solver/snapshot_particles.hpp"

namespace mpfd::mpm {

struct ServedZone {
  ServedZone(config::Scene scene_in, const cosim::v1::Setup& setup);

  config::Scene scene;
  std::string scene_text;            ///< Setup.scene_fragment, kept for checkpoints
  std::filesystem::path output_dir;  ///< Setup.output_dir (may be empty)
  MpmSolver solver;
  /// The scene's gauges with follow: material, bound at Setup to their particles (by id).
  FollowedGauges followed_gauges;
  std::map<std::string, ZoneRegion, std::less<>> regions;
  double setup_start_time;  ///< Setup.start_time [s]
  /// [s]: Setup's, or as an Activate of a dormant zone or a commit of imported
  /// fields set the clock (proto §5, §15 rule 4), or as a restored checkpoint had it.
  double start_time;
  bool dormant;
  std::optional<io::SnapshotWriter> snapshots;  // made at the first WriteOutput
  SnapshotParticles snapshot_fields;
  NodeBoxMap node_box_map;  ///< scratch of the NODES exports, kept so they do not allocate
  /// Wall time of the map a NODES export made for the next advance (MpmSolver::map_next_step) [s]
  double next_step_map_seconds = 0.0;
  ParticleScratch particle_scratch;  ///< scratch of the PARTICLES exports and removals
  std::optional<cosim::FieldAssembly> field_import;  ///< the FieldChunks of an import (v1.2)

  /// The coupled time t^n [s]: start_time plus the time advanced since.
  [[nodiscard]] double time() const { return start_time + solver.time(); }
  /// The region called `name`; throws cosim::ProtocolError{UNKNOWN_REGION} listing the known ones.
  [[nodiscard]] const ZoneRegion& region(const std::string& name, std::string_view operation) const;
};

/// Builds the zone of a Setup: zone kind MPM (or unspecified), scene_fragment
/// (YAML or JSON) through parse_scene (its domain is the zone's background
/// grid, its bodies the zone's particles; solver.method is not read), the zone grid
/// (if given) checked against the scene's cells, every region checked
/// (zone_region.hpp). Throws cosim::ProtocolError.
[[nodiscard]] std::unique_ptr<ServedZone> set_up_zone(const cosim::v1::Setup& setup);

/// SetupAck: the regions with the quantities served, and the first stable dt.
[[nodiscard]] cosim::v1::SetupAck setup_ack(const cosim::v1::Setup& setup, const ServedZone& zone);

}  // namespace mpfd::mpm
