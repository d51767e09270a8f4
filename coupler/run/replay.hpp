#pragma once
// `coupler replay FILE --solver NAME`: plays the coupler's side of a recorded
// run (proto §10) against one live solver and compares each of its replies
// with the recorded one. Exact comparison of everything deterministic: the
// result kinds, counts, times, proposed dt and every array value (bitwise, or
// within a relative tolerance); wall-clock fields and file lists are skipped.
// The first divergence is reported by step, message, field, index and values.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "coupler/run/solver_handle.hpp"

namespace mpfd::coupler {

struct ReplayOptions {
  std::string solver = "fdm";     ///< the peer to replay ("fdm" or "mpm")
  std::filesystem::path out_dir;  ///< replaces Setup.output_dir (solver output goes here)
  double tolerance = 0;           ///< 0: bitwise; else relative |a - b| / max(|a|, |b|)
  double timeout_seconds = 30;    ///< reply timeout
};

struct ReplayReport {
  std::uint64_t requests = 0;             ///< requests played
  std::uint64_t values_compared = 0;      ///< array values compared
  std::optional<std::string> divergence;  ///< the first one; nothing if every reply matched
};

/// Starts `serve` on a thread (embedded) and replays `recording` against it.
/// Throws mpfd::Error if the recording is unreadable or holds no session
/// with `options.solver`, or if the solver fails.
ReplayReport replay(const std::filesystem::path& recording, const ReplayOptions& options,
                    ServeFunction serve);

}  // namespace mpfd::coupler
