#pragma once
// `fdm_solver run`: a scene advanced to its end time with no coupler,
// writing the output layout of docs/output.md: snapshots at every
// output.interval, gauges at every output.gauge_interval (or every step),
// summary.json with throughput and the conservation audit, and a progress line.

#include <filesystem>

#include "common/config/scene.hpp"
#include "fdm_solver/euler_solver.hpp"

namespace mpfd::fdm {

struct RunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;
  bool overwrite = false;
  bool skip_quiet = true;
};

/// Runs the scene. On an error after output has started, summary.json says
/// "failed" with the message, everything written so far is kept, and the
/// error is rethrown.
void run_standalone(const config::Scene& scene, const RunOptions& options);

}  // namespace mpfd::fdm
