#pragma once
// `coupler run`: a CFDMP run (T §4.3) driven over protocol v1. The solvers are
// already started and connecting to `hub`; this does the session (Hello,
// Setup), the lockstep loop (dt = min of the proposals, one Exchange per solver
// per step, sent together), output at the scene's intervals (after an exchange
// without Advance that deposits the particles removed in the last step and
// exports the audit; the face parcels stay with the coupler and are counted in
// the audit), the conservation audit in summary.json, and
// Shutdown. On any failure it names the solver, shuts the other down, keeps
// what was written, writes summary.json with status "failed" and throws.

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "cosim/hub.hpp"
#include "cosim/serving/field_stream.hpp"
#include "coupler/run/coupler_checkpoint.hpp"
#include "coupler/run/solver_handle.hpp"

namespace mpfd::coupler {

struct CoupledRunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;
  std::optional<std::filesystem::path> record;  ///< write every message here (proto §10)
  bool progress = true;                         ///< progress line on a terminal
  /// Wall time between Pings to a sleeping MPM zone's solver (well inside its idle timeout).
  std::chrono::milliseconds keep_alive{1000};
  /// AFDMP handoffs: the largest FieldChunk frame (proto §15) and how long one
  /// chunk or commit may take (a whole-field commit can outlast a step's reply timeout).
  std::uint64_t max_chunk_bytes = cosim::kDefaultMaxChunkBytes;
  std::chrono::milliseconds handoff_timeout{300000};
  /// A checkpoint after every this many outputs (coupler_checkpoint.hpp); 0: none.
  int checkpoint_every = 0;
  /// Keep the newest this many checkpoints, removing older ones (prune_checkpoints); 0: all.
  int checkpoint_keep = 2;
  /// Go on from this checkpoint of the run in out_dir (newest_checkpoint).
  std::optional<CouplerCheckpoint> restart;
};

/// What the run measured (also in summary.json).
struct CoupledRunReport {
  std::int64_t steps = 0;
  double time = 0;
  double wall_seconds = 0;
  double fdm_advance_seconds = 0;  ///< Σ AdvanceResult.wall_seconds of the FDM
  double mpm_advance_seconds = 0;
  double max_advance_seconds = 0;  ///< Σ over steps of the slower solver's advance
  /// Steps whose dt the FDM's proposal, the MPM's or the strip cells' cap
  /// (strip_step_limit.hpp) set (output steps cut short are counted too).
  std::int64_t steps_limited_by_fdm = 0;
  std::int64_t steps_limited_by_mpm = 0;
  std::int64_t steps_limited_by_strip = 0;
  double mass_error = 0;  ///< relative, against the initial total
  double energy_error = 0;
};

/// Runs `scene` (cfdmp, text `scene_text` sent to the solvers in Setup) with
/// the solvers of `solvers` ("fdm", "mpm") connecting to `hub`. `out_dir` must
/// have been prepared (io::prepare_output_directory). Throws mpfd::Error.
CoupledRunReport run_cfdmp(const config::Scene& scene, const std::string& scene_text,
                           cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                           const CoupledRunOptions& options);

}  // namespace mpfd::coupler
