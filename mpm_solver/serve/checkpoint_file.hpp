#pragma once
// The contents of an MPM checkpoint file: every ParticleSet array (doubles in
// ParticleSet::for_each_double_array order, ids split in two exact halves),
// the materials of the injected bodies, clock, step, ledger, the scene text,
// the snapshot series written so far, and the box of a next-step map
// (MpmSolver::map_next_step), written and read back checked against the
// running zone.

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cosim/serving/checkpoint_clock.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

inline constexpr const char* kCheckpointFormat = "mpfd-mpm-checkpoint";
inline constexpr std::int64_t kCheckpointVersion = 3;

/// Writes the zone's whole restart state to `file` (created or overwritten), with
/// the box of its next-step map if it has one to keep (MpmSolver::next_step_map_for_checkpoint).
void write_checkpoint_file(const std::filesystem::path& file, const ServedZone& zone,
                           const std::optional<std::array<grid::Index3, 2>>& next_step_map_box);

/// A checkpoint read back: what MpmSolver::restore takes.
struct CheckpointContents {
  ParticleSet particles;
  std::vector<std::size_t> injected_body_materials;
  cosim::CheckpointClock clock;
  BoundaryLedger ledger;
  double particle_updates = 0.0;
  std::string scene_text;
  std::string snapshot_history;  ///< the snapshots written before it (io::SnapshotWriter::history)
  /// The node box the zone had mapped its next step for (MpmSolver::map_next_step), if any.
  std::optional<std::array<grid::Index3, 2>> next_step_map_box;
};

/// Reads `file` for `zone` at the Restore request's `step`. Throws a
/// non-fatal cosim::ProtocolError{IO} naming the file and what mismatched (format,
/// version, grid cells, materials, an array's size, step, Setup's start_time) and
/// mpfd::Error if HDF5 cannot read it.
[[nodiscard]] CheckpointContents read_checkpoint_file(const std::filesystem::path& file,
                                                      const ServedZone& zone, std::uint64_t step);

}  // namespace mpfd::mpm
