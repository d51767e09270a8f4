#include "mpm_solver/particle_generation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/core/error.hpp"
#include "common/eos/any_eos.hpp"

namespace mpfd::mpm {
namespace {

/// A body or a charge, resolved to the state its particles start in.
struct Source {
  const config::Shape* shape;
  std::size_t material;
  double density;
  grid::Vec3 velocity;
  double energy;
  int particles_per_axis;
  const grid::Vec3* detonation_point;  ///< program burn only
  double detonation_velocity;          ///< D [m/s] for charges, else 0
  std::string name;
};

std::size_t material_index(const config::Scene& scene, const std::string& name,
                           const std::string& where) {
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == name) return m;
  throw Error("scene '" + scene.name + "': " + where + ": unknown material '" + name + "'");
}

Source body_source(const config::Scene& scene, const config::Body& body) {
  const std::string where = "body '" + body.name + "'";
  const auto& s = body.state;
  const std::size_t m = material_index(scene, s.material, where);
  if (!(s.density > 0.0))
    throw Error("scene '" + scene.name + "': " + where + ": density must be > 0 kg/m^3, got " +
                std::to_string(s.density));
  const auto& eos = scene.materials[m].eos;
  const double e = s.specific_internal_energy ? *s.specific_internal_energy
                                              : eos::internal_energy(eos, s.density, *s.pressure);
  if (!std::isfinite(e))
    throw Error("scene '" + scene.name + "': " + where + ": material '" + s.material +
                "' cannot reach the given pressure at density " + std::to_string(s.density));
  return {&body.shape, m,   s.density, s.velocity, e, body.particles_per_axis,
          nullptr,     0.0, body.name};
}

Source charge_source(const config::Scene& scene, const config::Charge& charge) {
  const std::string where = "charge '" + charge.name + "'";
  const std::size_t m = material_index(scene, charge.material, where);
  const auto& material = scene.materials[m];
  const auto* jwl = std::get_if<eos::Jwl>(&material.eos);
  if (jwl == nullptr || !material.explosive)
    throw Error("scene '" + scene.name + "': " + where + ": material '" + charge.material +
                "' must use the jwl EOS and have an explosive section");
  const bool program = charge.burn == config::Burn::program;
  if (program && !charge.detonation_point)
    throw Error("scene '" + scene.name + "': " + where +
                ": burn: program needs a detonation_point");
  // Detonation products at the explosive's reference state, at rest (common/initial).
  return {&charge.shape,
          m,
          jwl->rho0,
          {0.0, 0.0, 0.0},
          jwl->detonation_energy / jwl->rho0,
          charge.particles_per_axis,
          program ? &*charge.detonation_point : nullptr,
          material.explosive->detonation_velocity,
          charge.name};
}

}  // namespace

GeneratedParticles generate_particles(const config::Scene& scene, const grid::UniformGrid& grid) {
  std::vector<Source> sources;
  for (const auto& b : scene.bodies) sources.push_back(body_source(scene, b));
  for (const auto& c : scene.charges) sources.push_back(charge_source(scene, c));
  if (sources.size() > std::numeric_limits<std::uint16_t>::max())
    throw Error("scene '" + scene.name + "': too many bodies and charges for mpm_solver (" +
                std::to_string(sources.size()) + ")");

  const auto& h = grid.spacing();
  double min_spacing = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
    if (grid.is_active(a)) min_spacing = std::min(min_spacing, h[a]);

  GeneratedParticles out;
  ParticleSet& ps = out.particles;
  for (std::size_t b = 0; b < sources.size(); ++b) {
    const Source& src = sources[b];
    const int n = src.particles_per_axis;
    BodyInfo info;
    info.name = src.name;
    info.material = src.material;
    info.particles_per_axis = n;
    for (int a = 0; a < 3; ++a) info.half_width[a] = grid.is_active(a) ? 0.5 / n : 0.5;
    info.characteristic_length = min_spacing / n;
    info.burn_rate = src.detonation_velocity / (1.5 * info.characteristic_length);  // T (3-2)
    out.bodies.push_back(info);

    // Cells the shape's bounding box overlaps, clamped to the grid.
    const config::Box box = config::bounding_box(*src.shape);
    grid::Index3 lo{}, hi{};
    int per_cell = 1;
    grid::Index3 count{};
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::clamp(static_cast<int>(std::floor((box.lower[a] - grid.origin()[a]) / h[a])), 0,
                         grid.cells()[a] - 1);
      hi[a] = std::clamp(static_cast<int>(std::floor((box.upper[a] - grid.origin()[a]) / h[a])), 0,
                         grid.cells()[a] - 1);
      count[a] = grid.is_active(a) ? n : 1;
      per_cell *= count[a];
    }
    const double volume = grid.cell_volume() / per_cell;
    const std::size_t first = ps.size();
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
          for (int sk = 0; sk < count[2]; ++sk)
            for (int sj = 0; sj < count[1]; ++sj)
              for (int si = 0; si < count[0]; ++si) {
                const int cell[3] = {i, j, k};
                const int sub[3] = {si, sj, sk};
                grid::Vec3 x{};
                for (int a = 0; a < 3; ++a)
                  x[a] = grid.origin()[a] + h[a] * (cell[a] + (sub[a] + 0.5) / count[a]);
                if (!config::contains(*src.shape, x)) continue;
                bool taken = false;  // by a later body or charge
                for (std::size_t later = b + 1; later < sources.size() && !taken; ++later)
                  taken = config::contains(*sources[later].shape, x);
                if (taken) continue;
                const std::size_t p = ps.size();
                ps.grow(1);
                for (int a = 0; a < 3; ++a) {
                  ps.position[a][p] = x[a];
                  ps.velocity[a][p] = src.velocity[a];
                }
                ps.density[p] = src.density;
                ps.mass[p] = src.density * volume;
                ps.specific_internal_energy[p] = src.energy;
                ps.material[p] = static_cast<std::uint16_t>(src.material);
                ps.body[p] = static_cast<std::uint16_t>(b);
                if (src.detonation_point) {  // T (3-2): t_L = distance / D
                  double d2 = 0.0;
                  for (int a = 0; a < 3; ++a) {
                    const double d = x[a] - (*src.detonation_point)[a];
                    d2 += d * d;
                  }
                  ps.lighting_time[p] = std::sqrt(d2) / src.detonation_velocity;
                }
              }
    if (ps.size() == first)
      throw Error("scene '" + scene.name +
                  "': " + (b < scene.bodies.size() ? "body '" : "charge '") + src.name +
                  "' holds no MPM particle (outside the domain, or covered by later "
                  "bodies)");
  }
  return out;
}

}  // namespace mpfd::mpm
