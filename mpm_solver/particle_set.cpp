#include "mpm_solver/particle_set.hpp"

#include <limits>

namespace mpfd::mpm {
namespace {

/// Moves the entries whose flag is 0 to the front, stride values per entry, and shrinks.
template <class T>
void compact(std::vector<T>& values, std::span<const std::uint8_t> flags, std::size_t stride) {
  std::size_t kept = 0;
  for (std::size_t p = 0; p < flags.size(); ++p) {
    if (flags[p] != 0) continue;
    if (kept != p)
      for (std::size_t k = 0; k < stride; ++k) values[kept * stride + k] = values[p * stride + k];
    ++kept;
  }
  values.resize(kept * stride);
}

}  // namespace

void ParticleSet::grow(std::size_t count) {
  const std::size_t n = size() + count;
  for_each_double_array([&](std::vector<double>& a, std::size_t stride) { a.resize(n * stride); });
  for (std::size_t p = n - count; p < n; ++p) {
    lighting_time[p] = -std::numeric_limits<double>::infinity();
    for (auto& f : stretch) f[p] = 1.0;
  }
  id.resize(n);
  material.resize(n);
  body.resize(n);
}

std::size_t ParticleSet::remove_flagged(std::span<const std::uint8_t> flags) {
  const std::size_t before = size();
  for_each_double_array(
      [&](std::vector<double>& a, std::size_t stride) { compact(a, flags, stride); });
  compact(id, flags, 1);
  compact(material, flags, 1);
  compact(body, flags, 1);
  return before - size();
}

Tensor3 ParticleSet::deviator(std::size_t p) const {
  const auto& s = deviatoric_stress;
  Tensor3 t;
  t << s[kXX][p], s[kXY][p], s[kZX][p],  //
      s[kXY][p], s[kYY][p], s[kYZ][p],   //
      s[kZX][p], s[kYZ][p], s[kZZ][p];
  return t;
}

void ParticleSet::set_deviator(std::size_t p, const Tensor3& t) {
  auto& s = deviatoric_stress;
  s[kXX][p] = t(0, 0);
  s[kYY][p] = t(1, 1);
  s[kZZ][p] = t(2, 2);
  s[kXY][p] = 0.5 * (t(0, 1) + t(1, 0));
  s[kYZ][p] = 0.5 * (t(1, 2) + t(2, 1));
  s[kZX][p] = 0.5 * (t(2, 0) + t(0, 2));
}

MaterialPoint ParticleSet::material_point(std::size_t p, Tensor3& s) {
  return {s,
          pressure[p],
          specific_internal_energy[p],
          sound_speed[p],
          equivalent_plastic_strain[p],
          plastic_work[p],
          damage[p],
          temperature[p],
          std::span<double>(history.data() + p * history_stride, history_stride)};
}

std::size_t nearest_particle(const ParticleSet& ps, const grid::Vec3& x) {
  std::size_t best = 0;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const double dx = ps.position[0][p] - x[0], dy = ps.position[1][p] - x[1],
                 dz = ps.position[2][p] - x[2];
    const double d2 = dx * dx + dy * dy + dz * dz;
    if (d2 < best_d2) {
      best_d2 = d2;
      best = p;
    }
  }
  return best;
}

}  // namespace mpfd::mpm
