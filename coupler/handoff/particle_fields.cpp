#include "coupler/handoff/particle_fields.hpp"

#include <string>

#include "common/core/error.hpp"

namespace mpfd::coupler::handoff {
namespace {

template <class T>
void require_count(std::span<const T> values, std::size_t expected, const char* what,
                   const char* name) {
  if (values.size() != expected)
    throw Error(std::string(what) + ": " + name + " must have " + std::to_string(expected) +
                " entries, got " + std::to_string(values.size()));
}

constexpr std::array<const char*, 3> kPositionNames{"position x", "position y", "position z"};
constexpr std::array<const char*, 3> kVelocityNames{"velocity x", "velocity y", "velocity z"};
constexpr std::array<const char*, 3> kMomentumNames{"momentum x", "momentum y", "momentum z"};

}  // namespace

void ParticleSet::resize(std::size_t n) {
  for (auto& x : position) x.resize(n);
  mass.resize(n);
  for (auto& v : velocity) v.resize(n);
  internal_energy.resize(n);
  pressure.resize(n);
  volume.resize(n);
  material.resize(n);
}

ParticleView ParticleSet::view() const {
  return {{position[0], position[1], position[2]},
          mass,
          {velocity[0], velocity[1], velocity[2]},
          internal_energy,
          material};
}

TracerView TracerPoints::view() const {
  return {{position[0], position[1], position[2]}, material};
}

void ConservedCells::assign(std::size_t cells) {
  density.assign(cells, 0.0);
  for (auto& p : momentum) p.assign(cells, 0.0);
  total_energy.assign(cells, 0.0);
}

ConservedView ConservedCells::view() const {
  return {density, {momentum[0], momentum[1], momentum[2]}, total_energy};
}

void check_sizes(const ParticleView& particles) {
  const std::size_t n = particles.size();
  for (int a = 0; a < 3; ++a) {
    require_count(particles.position[a], n, "particles", kPositionNames[a]);
    require_count(particles.velocity[a], n, "particles", kVelocityNames[a]);
  }
  require_count(particles.internal_energy, n, "particles", "internal_energy");
  require_count(particles.material, n, "particles", "material");
}

void check_sizes(const TracerView& tracers) {
  for (int a = 0; a < 3; ++a)
    require_count(tracers.position[a], tracers.size(), "tracers", kPositionNames[a]);
}

void check_sizes(const ConservedView& cells, std::size_t cell_count) {
  require_count(cells.density, cell_count, "cells", "density");
  for (int a = 0; a < 3; ++a)
    require_count(cells.momentum[a], cell_count, "cells", kMomentumNames[a]);
  require_count(cells.total_energy, cell_count, "cells", "total_energy");
}

}  // namespace mpfd::coupler::handoff
