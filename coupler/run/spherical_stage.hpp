#pragma once
// AFDMP's 1D start (solver.afdmp.start: spherical; seed S, T §4.4.3): the
// charge detonates in the 1D spherical MPM inside the coupler, while the
// solvers wait, until every explosive particle has burnt and the shock front
// has reached solver.afdmp.spherical.handoff_radius. Its particles then become
// the radial shells the Cartesian remap takes (design §3.5 H1s).
// The 1D run covers the ball of kReachFactor x handoff_radius about the
// charge's centre, with a transmitting outer surface.

#include <span>
#include <vector>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"
#include "coupler/remap/shells_from_particles.hpp"
#include "coupler/run/restart_file.hpp"
#include "mpm_solver/spherical/spherical_mpm.hpp"

namespace mpfd::coupler {

/// The 1D run's outer radius over the handoff radius (room for the front to arrive),
/// rounded down to the 1D grid; the scene check (scene_checks_afdmp) clears this ball.
inline constexpr double kReachFactor = 1.25;

class SphericalStage {
 public:
  /// Throws mpfd::Error (naming the scene) unless it has one spherical charge and
  /// solver.afdmp.spherical.handoff_radius.
  explicit SphericalStage(const config::Scene& scene);

  [[nodiscard]] double stable_dt() const { return mpm_.stable_dt(); }
  void advance(double dt) { mpm_.advance(dt); }
  [[nodiscard]] double time() const { return mpm_.time(); }
  [[nodiscard]] const grid::Vec3& centre() const { return centre_; }

  /// Every explosive particle has F = 1.
  [[nodiscard]] bool burn_complete() const;
  /// The outermost radius [m] whose pressure exceeds the ambient one by
  /// front_overpressure [Pa]; 0 before any does.
  [[nodiscard]] double front_radius() const;
  /// Pressure [Pa] at each scene gauge's distance from the centre.
  void gauge_pressures(std::span<double> out) const;

  /// The particles as radial shells with scene material indices (S step (1)).
  [[nodiscard]] remap::RadialShells shells() const;
  [[nodiscard]] mpm::spherical::SphericalTotals totals() const { return mpm_.totals(); }

  /// The 1D particles and clock as "/stage" of a coupled checkpoint
  /// (spherical_stage_checkpoint.cpp), and back into a stage built from the same scene.
  void save(RestartWriter& out) const;
  void restore(const RestartReader& in);

 private:
  const config::Scene& scene_;
  grid::Vec3 centre_{};
  std::vector<int> layer_material_;  ///< scene material index of each 1D layer
  double ambient_pressure_ = 0;
  mpm::spherical::SphericalMpm mpm_;
};

}  // namespace mpfd::coupler
