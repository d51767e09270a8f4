#pragma once
// The material points, structure of arrays: one std::vector per quantity, all
// of the same length. Every quantity a constitutive model reads or writes
// lives here (constitutive_model.hpp, MaterialPoint), so a step touches only
// contiguous arrays. Stress is split as sigma = s - (p + q) I (tension
// positive): s the deviator (six components), p the EOS pressure (times the
// burn fraction F for explosives) and q the artificial bulk viscosity.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "mpm_solver/material/constitutive_model.hpp"

namespace mpfd::mpm {

/// Components of the symmetric deviator, in this order (docs/output.md).
enum StressComponent : std::size_t { kXX, kYY, kZZ, kXY, kYZ, kZX };

/// Ids of the scene's own particles start here (bit 63), above any a coupler assigns.
inline constexpr std::uint64_t kSceneParticleIdBase = std::uint64_t{1} << 63;

struct ParticleSet {
  std::array<std::vector<double>, 3> position;           ///< x_p [m]
  std::array<std::vector<double>, 3> velocity;           ///< v_p [m/s]
  std::vector<double> mass;                              ///< m_p [kg], constant
  std::vector<double> density;                           ///< rho_p [kg/m^3]; volume = m_p / rho_p
  std::array<std::vector<double>, 6> deviatoric_stress;  ///< s [Pa], StressComponent order
  std::vector<double> pressure;                          ///< p [Pa] (times F for explosives)
  std::vector<double> bulk_viscosity;                    ///< q [Pa]
  std::vector<double> specific_internal_energy;          ///< e [J/kg]
  std::vector<double> sound_speed;                       ///< c [m/s]
  std::vector<double> equivalent_plastic_strain;         ///< [-]
  std::vector<double> plastic_work;                      ///< [J/kg]
  std::vector<double> damage;                            ///< [-]
  std::vector<double> temperature;                       ///< [K]
  std::vector<double> lighting_time;  ///< t_L of the program burn T (3-2) [s]; -inf: burnt/inert
  /// F_aa, the diagonal of the deformation gradient, updated by (1 + d eps_aa) each
  /// step (cpGIMP's domain stretch) [-]
  std::array<std::vector<double>, 3> stretch;
  /// Identity for a coupler (proto/README.md §6): its ids for injected particles,
  /// 2^63 + generation index for the scene's own.
  std::vector<std::uint64_t> id;
  std::vector<std::uint16_t> material;  ///< index into Scene::materials
  std::vector<std::uint16_t> body;      ///< index into MpmSolver::bodies()
  std::vector<double> history;          ///< history_stride() scalars per particle
  std::size_t history_stride = 0;       ///< the largest history_count() of the models

  [[nodiscard]] std::size_t size() const { return mass.size(); }

  /// Appends `count` particles with every quantity zero (lighting time -inf).
  void grow(std::size_t count);

  /// Keeps only the particles whose flag is 0. A removed particle's slot below the
  /// new size takes a kept particle from above it (lowest slot, lowest particle
  /// first), so a kept particle's index never grows. Returns how many were removed.
  std::size_t remove_flagged(std::span<const std::uint8_t> flags);

  /// The deviator of particle p as a tensor, and back.
  [[nodiscard]] Tensor3 deviator(std::size_t p) const;
  void set_deviator(std::size_t p, const Tensor3& s);

  /// The (per-particle) view a constitutive model works on; `s` is the caller's
  /// tensor copy of the deviator (see deviator()).
  [[nodiscard]] MaterialPoint material_point(std::size_t p, Tensor3& s);

  /// Every per-particle array of doubles, fn(array, values per particle), in a
  /// fixed order, for bulk operations (growth, removal, checkpoints).
  template <class Fn>
  void for_each_double_array(Fn&& fn) {
    visit_double_arrays(*this, fn);
  }
  template <class Fn>
  void for_each_double_array(Fn&& fn) const {
    visit_double_arrays(*this, fn);
  }

 private:
  template <class Self, class Fn>
  static void visit_double_arrays(Self& self, Fn& fn) {
    for (auto& a : self.position) fn(a, 1);
    for (auto& a : self.velocity) fn(a, 1);
    fn(self.mass, 1);
    fn(self.density, 1);
    for (auto& a : self.deviatoric_stress) fn(a, 1);
    for (auto* a : {&self.pressure, &self.bulk_viscosity, &self.specific_internal_energy,
                    &self.sound_speed, &self.equivalent_plastic_strain, &self.plastic_work,
                    &self.damage, &self.temperature, &self.lighting_time})
      fn(*a, 1);
    for (auto& a : self.stretch) fn(a, 1);
    fn(self.history, self.history_stride);
  }

  // remove_flagged()'s scratch: slots to fill and the particles that fill them.
  std::vector<std::size_t> holes_;
  std::vector<std::size_t> fillers_;
};

/// Index of the particle nearest to x (a gauge is an Eulerian point); 0 when there is none.
[[nodiscard]] std::size_t nearest_particle(const ParticleSet& ps, const grid::Vec3& x);

}  // namespace mpfd::mpm
