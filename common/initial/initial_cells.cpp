#include "common/initial/initial_cells.hpp"

#include <cmath>

#include "common/core/error.hpp"
#include "common/eos/any_eos.hpp"

namespace mpfd::initial {
namespace {

/// A resolved state: material index, density, velocity, e, burn fraction.
struct CellState {
  std::size_t material;
  double density;
  grid::Vec3 velocity;
  double energy;
  double burn;
};

std::size_t material_index(const config::Scene& scene, const std::string& name) {
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == name) return m;
  throw Error("scene '" + scene.name + "': unknown material '" + name + "'");
}

CellState resolve(const config::Scene& scene, const config::MaterialState& s,
                  const std::string& where) {
  const std::size_t m = material_index(scene, s.material);
  if (!(s.density > 0.0))
    throw Error("scene '" + scene.name + "': " + where + ": density must be > 0 kg/m^3, got " +
                std::to_string(s.density));
  const auto& eos = scene.materials[m].eos;
  const double e = s.specific_internal_energy ? *s.specific_internal_energy
                                              : eos::internal_energy(eos, s.density, *s.pressure);
  if (!std::isfinite(e))
    throw Error("scene '" + scene.name + "': " + where + ": material '" + s.material +
                "' cannot reach the given pressure at density " + std::to_string(s.density));
  return {m, s.density, s.velocity, e, 1.0};
}

CellState resolve_charge(const config::Scene& scene, const config::Charge& charge) {
  const std::size_t m = material_index(scene, charge.material);
  const auto* jwl = std::get_if<eos::Jwl>(&scene.materials[m].eos);
  if (jwl == nullptr)
    throw Error("scene '" + scene.name + "': charge '" + charge.name + "': material '" +
                charge.material + "' must use the jwl EOS");
  const double burn = charge.burn == config::Burn::instantaneous ? 1.0 : 0.0;
  return {m, jwl->rho0, {0.0, 0.0, 0.0}, jwl->detonation_energy / jwl->rho0, burn};
}

}  // namespace

void CellFields::resize(std::size_t cells) {
  for (auto* f : {&density, &velocity_x, &velocity_y, &velocity_z, &specific_internal_energy,
                  &pressure, &sound_speed, &material, &burn_fraction})
    f->assign(cells, 0.0);
}

grid::UniformGrid scene_grid(const config::Scene& scene) {
  return grid::UniformGrid::from_bounds(scene.domain.lower, scene.domain.upper, scene.domain.cells);
}

CellFields initial_cells(const config::Scene& scene, const grid::UniformGrid& grid) {
  const CellState background = resolve(scene, scene.initial, "initial");
  std::vector<CellState> bodies;
  for (const auto& b : scene.bodies)
    bodies.push_back(resolve(scene, b.state, "body '" + b.name + "'"));
  std::vector<CellState> charges;
  for (const auto& c : scene.charges) charges.push_back(resolve_charge(scene, c));

  CellFields f;
  f.resize(grid.cell_count());
  for (std::size_t n = 0; n < grid.cell_count(); ++n) {
    const grid::Vec3 x = grid.cell_center(grid.cell_of_index(n));
    const CellState* s = &background;
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (config::contains(scene.bodies[b].shape, x)) s = &bodies[b];
    for (std::size_t c = 0; c < charges.size(); ++c)
      if (config::contains(scene.charges[c].shape, x)) s = &charges[c];
    const auto& eos = scene.materials[s->material].eos;
    f.density[n] = s->density;
    f.velocity_x[n] = s->velocity[0];
    f.velocity_y[n] = s->velocity[1];
    f.velocity_z[n] = s->velocity[2];
    f.specific_internal_energy[n] = s->energy;
    f.pressure[n] = s->burn * eos::pressure(eos, s->density, s->energy);  // T (3-2)
    f.sound_speed[n] = eos::sound_speed(eos, s->density, s->energy);
    f.material[n] = static_cast<double>(s->material);
    f.burn_fraction[n] = s->burn;
  }
  return f;
}

}  // namespace mpfd::initial
