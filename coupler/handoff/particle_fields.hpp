#pragma once
// The whole-field data an AFDMP handoff moves (T §3.2), as structures of
// arrays: MPM particles, FDM cell conserved variables, massless tracers.
// Views are what the kernels read; the owning sets are what they return.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace mpfd::coupler::handoff {

struct ParticleView {
  std::array<std::span<const double>, 3> position;  ///< x, y, z [m]
  std::span<const double> mass;                     ///< m_p [kg]
  std::array<std::span<const double>, 3> velocity;  ///< v_ip [m/s]
  std::span<const double> internal_energy;          ///< e_p^int [J] (extensive, as in T (3-5))
  std::span<const int> material;                    ///< material index >= 0

  [[nodiscard]] std::size_t size() const { return mass.size(); }
};

/// Particles made by a handoff; sigma_p = -p_p I (T (3-17)).
struct ParticleSet {
  std::array<std::vector<double>, 3> position;
  std::vector<double> mass;
  std::array<std::vector<double>, 3> velocity;
  std::vector<double> internal_energy;  ///< [J]
  std::vector<double> pressure;         ///< p_p [Pa]
  std::vector<double> volume;           ///< V_p [m^3]; the MPM needs it (fdm_to_mpm.hpp)
  std::vector<int> material;

  [[nodiscard]] std::size_t size() const { return mass.size(); }
  void resize(std::size_t n);
  [[nodiscard]] ParticleView view() const;
};

struct TracerView {
  std::array<std::span<const double>, 3> position;  ///< [m]
  std::span<const int> material;

  [[nodiscard]] std::size_t size() const { return material.size(); }
};

/// Massless tracers: a position and a material, nothing else (T §3.2.1).
struct TracerPoints {
  std::array<std::vector<double>, 3> position;
  std::vector<int> material;

  [[nodiscard]] std::size_t size() const { return material.size(); }
  [[nodiscard]] TracerView view() const;
};

/// FDM conserved variables per cell, grid order (T (2-49)).
struct ConservedView {
  std::span<const double> density;                  ///< rho [kg/m^3]
  std::array<std::span<const double>, 3> momentum;  ///< rho v [kg/(m^2 s)]
  std::span<const double> total_energy;             ///< E [J/m^3]
};

struct ConservedCells {
  std::vector<double> density;
  std::array<std::vector<double>, 3> momentum;
  std::vector<double> total_energy;

  void assign(std::size_t cells);
  [[nodiscard]] ConservedView view() const;
};

/// Throws mpfd::Error naming the first array whose size is not the particle count.
void check_sizes(const ParticleView& particles);
void check_sizes(const TracerView& tracers);
/// Throws mpfd::Error unless every array has `cells` entries.
void check_sizes(const ConservedView& cells, std::size_t cell_count);

}  // namespace mpfd::coupler::handoff
