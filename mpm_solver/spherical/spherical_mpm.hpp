#pragma once
// One-dimensional spherically symmetric MPM (seed S): particles on a radial
// grid, explicit MUSL time integration as in T (2-13)-(2-21), materials through
// ConstitutiveModel. Built from concentric layers; the coupler reads radial
// profiles and remaps them onto a 3D grid (S §4). Equations: README.md.

#include <memory>
#include <vector>

#include "mpm_solver/material/constitutive_model.hpp"
#include "mpm_solver/spherical/particle_stress_update.hpp"
#include "mpm_solver/spherical/radial_grid.hpp"
#include "mpm_solver/spherical/radial_transfer.hpp"
#include "mpm_solver/spherical/spherical_particles.hpp"
#include "mpm_solver/spherical/spherical_setup.hpp"

namespace mpfd::mpm::spherical {

/// Particle profiles along r, ordered by radius. Masses per unit solid angle.
struct RadialProfile {
  std::vector<double> radius;                    ///< [m]
  std::vector<double> mass_per_steradian;        ///< [kg/sr]
  std::vector<double> velocity;                  ///< radial [m/s]
  std::vector<double> density;                   ///< [kg/m^3]
  std::vector<double> pressure;                  ///< EOS pressure (times F), without q [Pa]
  std::vector<double> specific_internal_energy;  ///< [J/kg]
  std::vector<double> stress_rr;                 ///< s_rr - p, without q [Pa]
  std::vector<double> stress_hoop;               ///< s_tt = s_pp - p, without q [Pa]
  std::vector<double> burn_fraction;             ///< F [-]
  std::vector<int> layer;                        ///< index of the particle's layer
};

/// Whole-sphere totals (4 pi times the per-steradian sums).
struct SphericalTotals {
  double mass = 0.0;             ///< [kg]
  double kinetic_energy = 0.0;   ///< [J]
  double internal_energy = 0.0;  ///< [J], including the unburnt explosive's E0
};

class SphericalMpm {
 public:
  /// Seeds particles (particle_seeding.hpp) and initialises every material.
  /// Throws mpfd::Error for bad layers or options.
  SphericalMpm(std::vector<RadialLayer> layers, SphericalOptions options);

  /// One explicit MUSL step of length dt [s]: T (2-9)-(2-21), S eqs. (7), (11), (16).
  void advance(double dt);
  /// cfl * min_p h / (Q_p + sqrt(Q_p^2 + c_p^2) + |v_p|), Q_p the viscous speed of S eq. (16).
  [[nodiscard]] double stable_dt() const;

  [[nodiscard]] double time() const noexcept { return time_; }
  [[nodiscard]] const SphericalParticles& particles() const noexcept { return particles_; }
  [[nodiscard]] const std::vector<RadialLayer>& layers() const noexcept { return layers_; }
  [[nodiscard]] const SphericalOptions& options() const noexcept { return options_; }
  /// Copies the particle state into profile (its vectors are reused).
  void export_profile(RadialProfile& profile) const;
  /// EOS pressure at radius r [Pa], linear between the two particles around r
  /// (the end particle's value outside them).
  [[nodiscard]] double pressure_at(double radius) const;
  [[nodiscard]] SphericalTotals totals() const;

  /// Continues from `particles` at `time` [s], a state this solver had (a checkpoint):
  /// the same particles of the same layers. Throws mpfd::Error, the solver unchanged,
  /// for another count, history stride or material order, or a time that is not >= 0.
  void restore(const SphericalParticles& particles, double time);

 private:
  std::vector<RadialLayer> layers_;
  SphericalOptions options_;
  std::vector<std::unique_ptr<ConstitutiveModel>> models_;
  MaterialTable materials_;
  StressUpdateSettings settings_;
  SphericalParticles particles_;
  RadialGrid grid_;
  ParticleWeights weights_;
  double ambient_pressure_ = 0.0;  ///< initial pressure of the outermost particle [Pa]
  double time_ = 0.0;
};

}  // namespace mpfd::mpm::spherical
