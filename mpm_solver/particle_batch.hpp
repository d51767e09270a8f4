#pragma once
// Particles crossing the MPM zone's boundary in a coupled run (T §4.3 steps
// 14, (4-15)...(4-21)): what a coupler injects and what a removal returns, in
// the layout of proto/README.md §3 (extensive quantities, Cauchy stress).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpm_solver/particle_set.hpp"

namespace mpfd::mpm {

/// Voigt components of a symmetric stress on the wire: xx, yy, zz, yz, xz, xy.
inline constexpr std::size_t kVoigt = 6;
/// The ParticleSet component of each wire Voigt component.
inline constexpr StressComponent kFromVoigt[kVoigt] = {kXX, kYY, kZZ, kYZ, kZX, kXY};

struct ParticleBatch {
  std::vector<std::uint64_t> id;
  std::vector<double> position;         ///< [m], [n, 3]
  std::vector<double> velocity;         ///< [m/s], [n, 3]
  std::vector<double> mass;             ///< [kg]
  std::vector<double> volume;           ///< [m^3]
  std::vector<double> internal_energy;  ///< m e [J]
  std::vector<std::uint32_t> material;  ///< index into Scene::materials
  std::vector<double> stress;  ///< Cauchy [Pa], [n, 6] Voigt; empty on injection: from the EOS

  [[nodiscard]] std::size_t size() const { return id.size(); }
  void resize(std::size_t n) {
    id.resize(n);
    position.resize(3 * n);
    velocity.resize(3 * n);
    mass.resize(n);
    volume.resize(n);
    internal_energy.resize(n);
    material.resize(n);
    stress.resize(kVoigt * n);
  }
};

/// A coupler's contribution to one background-grid node (T (4-7)...(4-9)).
struct NodeLoad {
  enum class Quantity { mass, momentum, force };
  std::array<int, 3> node{};  ///< grid node indices (0..cells on an active axis, 0 otherwise)
  Quantity quantity = Quantity::mass;
  bool overwrite = false;         ///< true: replaces the mapped value; false: adds to it
  std::array<double, 3> value{};  ///< [kg] (mass: value[0]), [kg m/s] or [N]
};

}  // namespace mpfd::mpm
