#pragma once
// The particles of the spherical MPM, structure of arrays. Masses and volumes
// are per unit solid angle (S eq. (1)): multiply by 4 pi for the whole sphere.
// Stress is diag(sigma_rr, sigma_tt, sigma_tt) in the local (r, theta, phi) frame;
// sigma = s - (p + q) I as in constitutive_model.hpp.

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

#include "mpm_solver/material/constitutive_model.hpp"

namespace mpfd::mpm::spherical {

struct SphericalParticles {
  static constexpr std::size_t kScalarFields = 15;
  template <class Field>
  using NamedFields = std::array<std::pair<const char*, Field*>, kScalarFields>;

  std::vector<double> radius;                     ///< r_p [m]
  std::vector<double> velocity;                   ///< radial v_p [m/s]
  std::vector<double> mass;                       ///< m_p per unit solid angle [kg/sr], S eq. (1)
  std::vector<double> density;                    ///< rho_p [kg/m^3]
  std::vector<double> pressure;                   ///< EOS pressure (times F) [Pa]
  std::vector<double> bulk_viscosity;             ///< q [Pa], S eq. (16)
  std::vector<double> volumetric_rate;            ///< epsdot_kk of the last step [1/s]
  std::vector<double> specific_internal_energy;   ///< e [J/kg]
  std::vector<double> sound_speed;                ///< c [m/s]
  std::vector<double> equivalent_plastic_strain;  ///< [-]
  std::vector<double> plastic_work;               ///< [J/kg]
  std::vector<double> damage;                     ///< [-]
  std::vector<double> temperature;                ///< [K]
  std::vector<Tensor3> deviatoric_stress;         ///< s [Pa], diagonal here
  std::vector<double> history;                    ///< history_stride scalars per particle
  std::vector<int> material;                      ///< index into the solver's layer materials
  std::vector<double> lighting_time;              ///< t_L = r0 / D [s], T (3-2); 0 for inert
  std::vector<double> burn_fraction;              ///< F [-], T (3-2); 1 for inert
  std::size_t history_stride = 0;

  [[nodiscard]] std::size_t size() const noexcept { return radius.size(); }
  void resize(std::size_t n, std::size_t stride);
  /// The arrays of one double per particle, by name (a checkpoint writes them so).
  [[nodiscard]] NamedFields<std::vector<double>> scalar_fields();
  [[nodiscard]] NamedFields<const std::vector<double>> scalar_fields() const;
  /// The constitutive state of particle p as a model sees it.
  [[nodiscard]] MaterialPoint point(std::size_t p);
  /// sigma_rr and sigma_tt including q [Pa].
  [[nodiscard]] double stress_rr(std::size_t p) const {
    return deviatoric_stress[p](0, 0) - pressure[p] - bulk_viscosity[p];
  }
  [[nodiscard]] double stress_hoop(std::size_t p) const {
    return deviatoric_stress[p](1, 1) - pressure[p] - bulk_viscosity[p];
  }
};

}  // namespace mpfd::mpm::spherical
