#pragma once
// `mpm_solver run` on a `domain.geometry: spherical` scene (METHOD.md V10):
// the 1D spherical MPM from the scene's layers (scene_layers.hpp) to its end
// time, with the standalone run's progress line and step loop. Writes
// gauges.csv/gauges.h5 (EOS pressure at each gauge's x = radius, every step or
// output.gauge_interval), a radial profile at every output.interval
// (profiles/profile_NNNNNN.csv, times in profiles/times.csv; README.md) and
// summary.json with the mass and energy audit.

#include <filesystem>

#include "common/config/scene.hpp"

namespace mpfd::mpm::spherical {

struct SphericalRunOptions {
  std::filesystem::path scene_file;
  std::filesystem::path out_dir;
  bool overwrite = false;
};

/// Runs the scene; throws mpfd::Error unless its geometry is spherical. On an
/// error after output has started, summary.json says "failed" with the
/// message, what was written is kept, and the error is rethrown.
void run_spherical(const config::Scene& scene, const SphericalRunOptions& options);

}  // namespace mpfd::mpm::spherical
