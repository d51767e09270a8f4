#pragma once
// A coupled CFDMP run's checkpoint (`coupler run --checkpoint-every K`,
// docs/coupler.md "Checkpoint and restart"). After every K-th output's
// exchange, when neither solver holds a half-done step, the coupler asks each
// awake solver for its own checkpoint (proto/README.md §8; a sleeping MPM zone
// is still its Setup's state) and then writes its own state to
// <out>/checkpoints/coupler_NNNNNN.h5 (NNNNNN = the coupled step), renamed into
// place last: a coupler file names a complete set. `coupler run --restart`
// continues from the newest one: Setup, Restore of each solver's file, the
// coupler's state, then the run goes on bit for bit.
//
// The file: attributes `format` "mpfd-coupler-checkpoint", `format_version`,
// `scene_sha256` (of the scene text: a restart refuses another scene),
// `dimension`, `step`, `time` [s], `outputs` (written so far), and per solver
// `<name>_path`, `<name>_step` ("" and 0 for a sleeping zone); then the groups
// of restart_file.hpp ("/loop", "/step", "/gauges", "/activation").

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "common/io/hdf5_file.hpp"

namespace mpfd::coupler {

inline constexpr const char* kCouplerCheckpointFormat = "mpfd-coupler-checkpoint";
inline constexpr std::int64_t kCouplerCheckpointVersion = 1;

/// A solver's checkpoint as its CheckpointWritten named it.
struct SolverCheckpoint {
  std::string path;
  std::uint64_t step = 0;  ///< Restore's step
};

/// A coupler checkpoint's header.
struct CouplerCheckpoint {
  std::filesystem::path file{};
  std::int64_t step = 0;                         ///< coupled steps done
  double time = 0;                               ///< t^n [s]
  int outputs = 0;                               ///< outputs written (the next one's index)
  std::optional<SolverCheckpoint> fdm{}, mpm{};  ///< none: the solver was asleep
};

/// <out_dir>/checkpoints/coupler_NNNNNN.h5 of `step`.
[[nodiscard]] std::filesystem::path coupler_checkpoint_file(const std::filesystem::path& out_dir,
                                                            std::int64_t step);

/// Writes the header of `checkpoint` for the scene text `scene_text` of `dimension`.
void write_checkpoint_header(io::Hdf5File& file, const CouplerCheckpoint& checkpoint,
                             const std::string& scene_text, int dimension);

/// The newest coupler checkpoint in <out_dir>/checkpoints, its header checked against
/// the scene. Throws mpfd::Error naming the folder when it holds none, and the file
/// and the attribute when it was written for another scene or format.
[[nodiscard]] CouplerCheckpoint newest_checkpoint(const std::filesystem::path& out_dir,
                                                  const std::string& scene_text, int dimension);

}  // namespace mpfd::coupler
