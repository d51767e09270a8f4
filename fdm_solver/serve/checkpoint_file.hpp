#pragma once
// The contents of a checkpoint file, docs/output.md `checkpoint_NNNNNN.h5`:
// everything the zone's next step reads (cells, clock, the outflow audit per
// face and boundary cell, the snapshot series written so far and, in a
// multi-material zone, the tracker's state),
// written and read back checked against the running zone.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "cosim/serving/checkpoint_clock.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// The `format` attribute of a checkpoint and the version read back.
inline constexpr const char* kCheckpointFormat = "mpfd-fdm-checkpoint";
inline constexpr std::int64_t kCheckpointVersion = 4;

/// Writes the zone's whole restart state to `file` (created or overwritten).
void write_checkpoint_file(const std::filesystem::path& file, const ServedZone& zone);

/// A checkpoint read back, checked to fit the zone: what EulerSolver::restore takes.
struct CheckpointContents {
  EulerState state;
  cosim::CheckpointClock clock{};
  Totals outflow{};
  FaceOutflow face_outflow{};
  std::optional<TrackerState> tracker{};
  std::string scene_text{};
  std::string snapshot_history{};  ///< the snapshots written before it (SnapshotOutput::history)
};

/// Reads `file` for `zone` at the Restore request's `step`. Throws a
/// non-fatal cosim::ProtocolError{IO} naming the file and what mismatched (format,
/// version, grid cells, material count or names, an array's size or values,
/// step, Setup's start_time) and mpfd::Error if HDF5 cannot read it.
[[nodiscard]] CheckpointContents read_checkpoint_file(const std::filesystem::path& file,
                                                      const ServedZone& zone, std::uint64_t step);

}  // namespace mpfd::fdm
