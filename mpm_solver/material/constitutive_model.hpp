#pragma once
// The seam between the MPM time step and the materials. The step (T (2-18)-(2-21))
// computes the strain and spin increments, the new density and the Jaumann
// rotation of the deviatoric stress; a ConstitutiveModel then does the rest of
// (2-21): the stress increment, the pressure from its equation of state, the
// internal energy (2-4) and its history variables. A new model (HJC, RHT,
// JH-2, Drucker-Prager) is a new class behind this interface plus one line in
// make_constitutive_model(); the time step does not change.
//
// Sign convention: Cauchy stress, tension positive; sigma = s - (p + q) I with
// s the deviator, p the EOS pressure and q the artificial bulk viscosity.

#include <Eigen/Core>
#include <memory>
#include <span>
#include <string_view>

namespace mpfd::config {
struct Material;
}

namespace mpfd::mpm {

using Tensor3 = Eigen::Matrix3d;

/// What the time step hands a model for one particle and one step.
struct StrainStep {
  Tensor3 strain_increment = Tensor3::Zero();  ///< Delta eps (2-18), symmetric [-]
  double dt = 0.0;                             ///< [s]
  double density_old = 0.0;                    ///< rho^n [kg/m^3]
  double density_new = 0.0;                    ///< rho^{n+1} (2-20) [kg/m^3]
  double bulk_viscosity = 0.0;                 ///< q^{n+1} [Pa], already computed by the step
  double burn_fraction = 1.0;                  ///< F of the program burn T (3-2) [-], 1 for inert
};

/// One particle's constitutive state: references into the particle arrays
/// (structure-of-arrays), so a model reads and writes them in place.
struct MaterialPoint {
  Tensor3& deviatoric_stress;         ///< s [Pa]: on entry Jaumann-rotated s^n, on exit s^{n+1}
  double& pressure;                   ///< p [Pa] from the EOS (times F for explosives)
  double& specific_internal_energy;   ///< e [J/kg], (2-4)
  double& sound_speed;                ///< c [m/s], for the stable time step
  double& equivalent_plastic_strain;  ///< [-]
  double& plastic_work;               ///< specific plastic work [J/kg]
  double& damage;             ///< D in [0, 1]; 1 = failed (no deviatoric stress, no tension)
  double& temperature;        ///< [K]; models without one leave it alone
  std::span<double> history;  ///< model-specific extra scalars, history_count() of them
};

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;

  /// Extra per-particle scalars the model keeps (porosity, volumetric plastic strain, ...).
  [[nodiscard]] virtual int history_count() const { return 0; }
  /// Sets pressure, sound speed, temperature and history of a particle that
  /// starts at density rho with specific internal energy e and zero deviator.
  virtual void initialise(double rho, MaterialPoint& point) const = 0;
  /// Advances the point by one step: s, p, e, c and the history variables.
  virtual void update(const StrainStep& step, MaterialPoint& point) const = 0;
  /// The model's name for messages and output, e.g. "johnson_cook+mie_gruneisen".
  [[nodiscard]] virtual std::string_view name() const = 0;
};

/// The model a scene's material asks for (its EOS plus its strength section).
/// Throws mpfd::Error naming the material for a combination it does not know.
[[nodiscard]] std::unique_ptr<ConstitutiveModel> make_constitutive_model(
    const config::Material& material);

}  // namespace mpfd::mpm
