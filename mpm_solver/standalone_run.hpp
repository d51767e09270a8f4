#pragma once
// `mpm_solver run`: a scene advanced to its end time with no coupler, writing
// the output layout of docs/output.md: particle snapshots at every
// output.interval (particles.xmf), gauges at every output.gauge_interval (or
// every step) read from the particle nearest to each gauge (or, with follow:
// material, from the particle bound to it at t = 0), summary.json with
// particle-updates per second and the audit (mass, momentum, energy and what
// left through the faces), and a progress line.

#include <filesystem>

#include "common/config/scene.hpp"

namespace mpfd::mpm {

struct RunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;
  bool overwrite = false;
};

/// Runs the scene (its solver.method must be mpm). On an error after output
/// has started, summary.json says "failed" with the message, everything
/// written so far is kept, and the error is rethrown.
void run_standalone(const config::Scene& scene, const RunOptions& options);

}  // namespace mpfd::mpm
