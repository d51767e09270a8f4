#pragma once
// Gauges that follow the material (the thesis's tracking points, T §3.4.4): a
// scene gauge with `follow: material` is bound at the start of the run to the
// particle nearest its position and then reads that particle wherever it
// moves. The binding holds the particle's id (ParticleSet::id), not its index,
// so it survives removal and reordering of the arrays; once the particle has
// left (removed at an outflow face), the gauge reads nothing.

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/config/scene.hpp"
#include "common/grid/uniform_grid.hpp"
#include "mpm_solver/particle_set.hpp"

namespace mpfd::mpm {

/// One cell of `grid` [m]: the largest spacing along the axes with more than
/// one cell (the spacing of a 1-cell axis is the slab's thickness, not a cell).
[[nodiscard]] double binding_reach(const grid::UniformGrid& grid);

/// Id of the particle nearest `gauge.position`, the lowest id among equally
/// near ones. Throws mpfd::Error naming the gauge, its position and the
/// nearest distance when no particle lies within `reach` [m].
[[nodiscard]] std::uint64_t bind_to_particle(const ParticleSet& ps, const config::Gauge& gauge,
                                             double reach);

class FollowedGauges {
 public:
  /// The particle a gauge follows has left the domain.
  static constexpr std::size_t kLeft = std::numeric_limits<std::size_t>::max();

  FollowedGauges() = default;
  /// Binds every gauge with follow: material to its particle in `ps` now
  /// (bind_to_particle); the others are not held.
  FollowedGauges(std::span<const config::Gauge> gauges, const ParticleSet& ps, double reach);

  /// Whether the gauge called `name` follows a particle.
  [[nodiscard]] bool follows(std::string_view name) const;
  /// Index in `ps` of the particle gauge `name` follows, or kLeft once it is
  /// gone. Throws mpfd::Error when `name` does not follow a particle.
  [[nodiscard]] std::size_t particle(std::string_view name, const ParticleSet& ps);
  /// The bound particle's id (same precondition as particle()).
  [[nodiscard]] std::uint64_t id(std::string_view name) const;

 private:
  struct Binding {
    std::string name;
    std::uint64_t id;
    std::size_t hint;  ///< where the particle was last found
  };
  [[nodiscard]] std::size_t binding(std::string_view name) const;  ///< index in bindings_
  std::vector<Binding> bindings_;
};

}  // namespace mpfd::mpm
