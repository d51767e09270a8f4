#pragma once
// A coupled run's checkpoint (`coupler run --checkpoint-every K`,
// docs/coupler.md "Checkpoint and restart"). After every K-th output (CFDMP:
// after its exchange, when neither solver holds a half-done step; AFDMP: in
// any phase), the coupler asks each solver that holds state for its own
// checkpoint (proto/README.md §8; a sleeping MPM zone, or AFDMP's FDM before the
// blast is handed to it, is still its Setup's state; a retired solver has none)
// and then writes its own state (AFDMP's 1D stage included) to
// <out>/checkpoints/coupler_NNNNNN.h5 (NNNNNN = the coupled step), renamed into
// place last: a coupler file names a complete set. `coupler run --restart`
// continues from the newest one: Setup, Restore of each solver's file, the
// coupler's state, then the run goes on bit for bit.
//
// The file: attributes `format` "mpfd-coupler-checkpoint", `format_version`,
// `scene_sha256` (of the scene text: a restart refuses another scene),
// `dimension`, `step`, `time` [s], `outputs` (written so far), `wall_seconds`, and per solver
// `<name>_path` (relative to the output folder when it lies in it, so the folder
// may move), `<name>_step` ("" and 0 for a sleeping zone); then the groups
// of restart_file.hpp (CFDMP: "/loop", "/step", "/gauges", "/activation";
// AFDMP: "/afdmp", "/audit", "/phases", "/gauges", "/activation", and "/stage"
// while the 1D stage runs).

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "common/io/hdf5_file.hpp"
#include "cosim/hub.hpp"
#include "coupler/run/restart_file.hpp"

namespace mpfd::coupler {

inline constexpr const char* kCouplerCheckpointFormat = "mpfd-coupler-checkpoint";
/// 2 (2026-12-07): AFDMP's "/stage" and the face-drain watch's last two deposits.
inline constexpr std::int64_t kCouplerCheckpointVersion = 2;

/// A solver's checkpoint as its CheckpointWritten named it.
struct SolverCheckpoint {
  std::string path;
  std::uint64_t step = 0;  ///< Restore's step
};

/// Where a run's step loop starts: t^n [s], steps done, outputs written.
struct RunPosition {
  double time = 0;
  std::int64_t step = 0;
  int outputs = 0;
};

/// A coupler checkpoint's header.
struct CouplerCheckpoint {
  std::filesystem::path file{};
  std::int64_t step = 0;    ///< coupled steps done
  double time = 0;          ///< t^n [s]
  int outputs = 0;          ///< outputs written (the next one's index)
  double wall_seconds = 0;  ///< the run's wall time up to it [s] (a restart's timings add it)
  std::optional<SolverCheckpoint> fdm{}, mpm{};  ///< none: the solver was asleep

  [[nodiscard]] RunPosition position() const { return {time, step, outputs}; }
  /// Opens `file` and hands the coupler's state in it to `restore`.
  void read_state(const std::function<void(const RestartReader&)>& restore) const;
};

/// What a run loop keeps of its checkpoints: when one is due, which older ones go,
/// summary.json's details.checkpoints, and, in a restarted run, the wall time before it
/// and whether the run is restored far enough for its summary to replace the stopped run's.
class CheckpointLog {
 public:
  /// `every`: --checkpoint-every (0: none); `keep`: --checkpoint-keep (0: all);
  /// `restarting`: --restart.
  CheckpointLog(int every, int keep, bool restarting);

  /// After `outputs` outputs (output 0 included), when the run goes on: one is due.
  [[nodiscard]] bool due(int outputs, bool run_goes_on) const;
  /// `checkpoint` is in place: the older ones beyond `keep` go (prune_checkpoints).
  void taken(const CouplerCheckpoint& checkpoint);
  /// The run is restored from `from`.
  void restarted(const CouplerCheckpoint& from);

  [[nodiscard]] double earlier_wall_seconds() const { return earlier_wall_seconds_; }
  [[nodiscard]] bool summary_ready() const { return summary_ready_; }
  [[nodiscard]] const nlohmann::json& summary() const { return summary_; }

 private:
  void remember(const CouplerCheckpoint& checkpoint);

  int every_;
  int keep_;
  int removed_ = 0;
  bool summary_ready_;
  double earlier_wall_seconds_ = 0;
  nlohmann::json summary_;
};

/// <out_dir>/checkpoints/coupler_NNNNNN.h5 of `step`.
[[nodiscard]] std::filesystem::path coupler_checkpoint_file(const std::filesystem::path& out_dir,
                                                            std::int64_t step);

/// Writes the header of `checkpoint` (its `file` in <out>/checkpoints/) for the scene
/// text `scene_text` of `dimension`.
void write_checkpoint_header(io::Hdf5File& file, const CouplerCheckpoint& checkpoint,
                             const std::string& scene_text, int dimension);

/// Removes the checkpoints an earlier run left in `out_dir` (the coupler's and the
/// solvers'): a run started afresh there must not be restarted from them.
void remove_checkpoints(const std::filesystem::path& out_dir);

/// The newest coupler checkpoint in <out_dir>/checkpoints, its header checked against
/// the scene. Throws mpfd::Error naming the folder when it holds none or its run has
/// completed, and the file and the attribute when it was written for another scene or
/// format.
[[nodiscard]] CouplerCheckpoint newest_checkpoint(const std::filesystem::path& out_dir,
                                                  const std::string& scene_text, int dimension);

/// Takes a coupled checkpoint at `at`, `wall_seconds` into the run: each of `peers` writes its own
/// as <its output_dir>/checkpoints/coupled_NNNNNN.h5, NNNNNN = at.step (all at once, waiting
/// `timeout` for each: a large grid outlasts a step's reply), then `save`
/// writes the coupler's state after the header into <out_dir>/checkpoints/coupler_NNNNNN.h5,
/// written beside it and renamed into place last, and logs it with its wall time. Returns what
/// was written. Throws mpfd::Error naming a solver that answers otherwise.
CouplerCheckpoint take_checkpoint(cosim::Hub& hub, const RunPosition& at, double wall_seconds,
                                  const std::filesystem::path& out_dir,
                                  const std::vector<std::string>& peers,
                                  std::chrono::milliseconds timeout, const std::string& scene_text,
                                  int dimension, const std::function<void(RestartWriter&)>& save);

/// Keeps the newest `keep` coupler checkpoints of <out_dir>/checkpoints (0: all). Each older
/// one is removed first, then the solver checkpoints (and their .sha256) that it names and no
/// kept one does, where they lie in `out_dir` (a solver on another host keeps its own).
/// Returns how many coupler checkpoints were removed; a file that cannot be read or
/// removed is a warning and stays (the run goes on).
int prune_checkpoints(const std::filesystem::path& out_dir, int keep);

/// Sends each solver that has a file in `from` its Restore, all at once, and checks the
/// Restored step (a zone that slept, or had been retired, has none: it stays as Setup
/// made it). Waits `timeout` for each (a large grid takes longer than a step's reply).
/// Throws mpfd::Error.
void restore_solvers(cosim::Hub& hub, const CouplerCheckpoint& from,
                     std::chrono::milliseconds timeout);

}  // namespace mpfd::coupler
