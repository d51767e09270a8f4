#pragma once
// The FDM zone a coupler set up (proto/README.md §5 Setup): the scene, the
// solver built from it, the named cell and tracer regions, the snapshot
// output and a whole-field import in progress (v1.2, proto/README.md §15).

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "common/config/scene.hpp"
#include "cosim/message.hpp"
#include "cosim/serving/field_stream.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/serve/cell_region.hpp"
#include "fdm_solver/serve/snapshot_output.hpp"
#include "fdm_solver/serve/tracer_region.hpp"

namespace mpfd::fdm {

struct ServedZone {
  ServedZone(config::Scene scene_in, const cosim::v1::Setup& setup);

  config::Scene scene;
  std::string scene_text;            ///< Setup.scene_fragment, kept for checkpoints
  std::filesystem::path output_dir;  ///< Setup.output_dir (may be empty)
  EulerSolver solver;
  std::map<std::string, CellRegion, std::less<>> regions;
  std::map<std::string, TracerRegion, std::less<>> tracer_regions;  ///< v1.2 TRACERS regions
  std::optional<cosim::FieldAssembly> pending_import;  ///< FieldChunks before their commit
  SnapshotOutput output;
  double setup_start_time;  ///< Setup.start_time [s]
  /// [s]: Setup's, or as a commit of imported fields sets the clock (proto
  /// README §15 rule 4), or as a restored checkpoint had it.
  double start_time;

  /// The coupled time t^n [s]: start_time plus the time advanced since.
  [[nodiscard]] double time() const { return start_time + solver.time(); }
  /// The region called `name`; throws cosim::ProtocolError{UNKNOWN_REGION} listing the known ones.
  [[nodiscard]] const CellRegion& region(const std::string& name, std::string_view operation) const;
  /// The TRACERS region called `name`, or null.
  [[nodiscard]] const TracerRegion* tracer_region(std::string_view name) const;
  /// Throws cosim::ProtocolError{UNKNOWN_REGION} (fatal as given) naming `name`
  /// and listing the declared regions of both kinds.
  [[noreturn]] void unknown_region(std::string_view name, std::string_view operation,
                                   bool fatal = true) const;
};

/// Builds the zone of a Setup: scene_fragment (the scene file's YAML or JSON
/// text) through parse_scene, the zone's grid (if given) checked against the
/// scene's cells, every region checked (cell_region.hpp). Throws cosim::ProtocolError.
[[nodiscard]] std::unique_ptr<ServedZone> set_up_zone(const cosim::v1::Setup& setup);

/// SetupAck: the regions with the quantities served, and the first stable dt.
[[nodiscard]] cosim::v1::SetupAck setup_ack(const cosim::v1::Setup& setup, const ServedZone& zone);

}  // namespace mpfd::fdm
