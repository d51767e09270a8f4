#pragma once
// Runs one scene of the stability suite in one solver at a given CFL number
// and returns what a judge of stability needs: how it ended (reached the end,
// or stopped by mpfd::Error with its message) and the state at half the end
// time and at the end as cells (FDM) and particles (MPM), both in one list.
//
// FDM and MPM are driven through their solver APIs, which take any CFL (the
// scene check allows (0, 1] only: docs/stability.md says why the sweep does
// not relax it); CFDMP runs through coupler::launch_run on a scene file,
// embedded, so its CFL is the scene's and at most 1.

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tests/stability/stability_scenes.hpp"

namespace mpfd::stability {

/// Cells or particles at one time: centre or position [m], density
/// [kg/m^3], speed |u| [m/s], pressure [Pa], volume [m^3].
struct Samples {
  std::vector<double> x, y, density, speed, pressure, volume;

  /// False if any value is NaN or infinite.
  [[nodiscard]] bool finite() const;
  [[nodiscard]] double max_pressure() const;
  /// sum rho |u|^2 / 2 V [J]
  [[nodiscard]] double kinetic_energy() const;
  /// Volume-weighted mean |rho - exact(x)| over the samples in [x_min, x_max] [kg/m^3].
  [[nodiscard]] double mean_density_error(const std::function<double(double)>& exact,
                                          double x_min = -INFINITY, double x_max = INFINITY) const;
};

struct Outcome {
  bool stopped = false;  ///< an mpfd::Error ended the run
  std::string message;   ///< its message
  std::int64_t steps = 0;
  Samples half;  ///< at end / 2 (empty if stopped before)
  Samples end;   ///< at the end (empty if stopped before)
};

/// Runs scene text `scene` (stability_scenes.hpp) at Courant number `cfl`
/// (FDM and MPM; CFDMP always runs at the scene's).
/// `work`: a folder for the CFDMP run's scene file and output (replaced).
/// Without `cfl` the solvers use the scene's (time.cfl or their defaults).
[[nodiscard]] Outcome run_scene(const std::string& scene, Solver solver, std::optional<double> cfl,
                                const std::filesystem::path& work);

}  // namespace mpfd::stability
