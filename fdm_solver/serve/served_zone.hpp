#pragma once
// The FDM zone a coupler set up (proto/README.md §5 Setup): the scene, the
// solver built from it, the named cell regions and the snapshot output.

#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "common/config/scene.hpp"
#include "cosim/message.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/serve/cell_region.hpp"
#include "fdm_solver/serve/snapshot_output.hpp"

namespace mpfd::fdm {

struct ServedZone {
  ServedZone(config::Scene scene_in, const cosim::v1::Setup& setup);

  config::Scene scene;
  std::string scene_text;            ///< Setup.scene_fragment, kept for checkpoints
  std::filesystem::path output_dir;  ///< Setup.output_dir (may be empty)
  EulerSolver solver;
  std::map<std::string, CellRegion, std::less<>> regions;
  SnapshotOutput output;
  double start_time;

  /// The coupled time t^n [s]: Setup's start_time plus the time advanced since.
  [[nodiscard]] double time() const { return start_time + solver.time(); }
  /// The region called `name`; throws cosim::ProtocolError{UNKNOWN_REGION} listing the known ones.
  [[nodiscard]] const CellRegion& region(const std::string& name, std::string_view operation) const;
};

/// Builds the zone of a Setup: scene_fragment (the scene file's YAML or JSON
/// text) through parse_scene, the zone's grid (if given) checked against the
/// scene's cells, every region checked (cell_region.hpp). Throws cosim::ProtocolError.
[[nodiscard]] std::unique_ptr<ServedZone> set_up_zone(const cosim::v1::Setup& setup);

/// SetupAck: the regions with the quantities served, and the first stable dt.
[[nodiscard]] cosim::v1::SetupAck setup_ack(const cosim::v1::Setup& setup, const ServedZone& zone);

}  // namespace mpfd::fdm
