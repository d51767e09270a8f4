#include "mpm_solver/cell_fields.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

int cell_along(const grid::UniformGrid& grid, int axis, double x) {
  const int n = grid.cells()[axis];
  if (n == 1) return 0;
  const double i = std::floor((x - grid.origin()[axis]) / grid.spacing()[axis]);
  return static_cast<int>(std::clamp(i, 0.0, static_cast<double>(n - 1)));
}

}  // namespace

std::size_t cell_holding(const grid::UniformGrid& grid, double x, double y, double z) {
  return grid.cell_index(cell_along(grid, 0, x), cell_along(grid, 1, y), cell_along(grid, 2, z));
}

CellFields::CellFields(const config::Scene& scene, const grid::UniformGrid& grid)
    : grid_(grid), fields_(scene.output.fields) {
  for (const auto& m : scene.materials) material_names_.push_back(m.name);
  const std::size_t cells = grid_.cell_count();
  mass_.assign(cells, 0.0);
  volume_.assign(cells, 0.0);
  for (const config::Field f : fields_) {
    switch (f) {
      case config::Field::density:
        density_.assign(cells, 0.0);
        break;
      case config::Field::velocity:
        for (auto& v : velocity_) v.assign(cells, 0.0);
        break;
      case config::Field::pressure:
        pressure_.assign(cells, 0.0);
        break;
      case config::Field::specific_internal_energy:
        energy_.assign(cells, 0.0);
        break;
      case config::Field::sound_speed:
        sound_speed_.assign(cells, 0.0);
        break;
      case config::Field::burn_fraction:
        burn_.assign(cells, 0.0);
        break;
      case config::Field::material:
        material_.assign(cells, -1.0);
        material_volume_.assign(cells * material_names_.size(), 0.0);
        break;
      case config::Field::volume_fraction:
        material_volume_.assign(cells * material_names_.size(), 0.0);
        break;
    }
  }
}

void CellFields::bin(const MpmSolver& solver) {
  const ParticleSet& ps = solver.particles();
  const std::size_t cells = grid_.cell_count();
  const auto zero = [](std::vector<double>& v) { std::fill(v.begin(), v.end(), 0.0); };
  for (auto* v : {&mass_, &volume_, &density_, &pressure_, &energy_, &sound_speed_, &burn_,
                  &material_volume_})
    zero(*v);
  for (auto& v : velocity_) zero(v);
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const std::size_t c =
        cell_holding(grid_, ps.position[0][p], ps.position[1][p], ps.position[2][p]);
    const double m = ps.mass[p];
    const double v = m / ps.density[p];
    mass_[c] += m;
    volume_[c] += v;
    for (int a = 0; a < 3; ++a)
      if (!velocity_[a].empty()) velocity_[a][c] += m * ps.velocity[a][p];
    if (!pressure_.empty()) pressure_[c] += v * ps.pressure[p];
    if (!energy_.empty()) energy_[c] += m * ps.specific_internal_energy[p];
    if (!sound_speed_.empty()) sound_speed_[c] += m * ps.sound_speed[p];
    if (!burn_.empty()) burn_[c] += m * solver.burn_fraction(p);
    if (!material_volume_.empty()) material_volume_[ps.material[p] * cells + c] += v;
  }
  const double cell_volume = grid_.cell_volume();
  for (std::size_t c = 0; c < cells; ++c) {
    const double m = mass_[c];
    const double inv_m = m > 0.0 ? 1.0 / m : 0.0;
    const double inv_v = volume_[c] > 0.0 ? 1.0 / volume_[c] : 0.0;
    if (!density_.empty()) density_[c] = m / cell_volume;
    for (auto& vel : velocity_)
      if (!vel.empty()) vel[c] *= inv_m;
    if (!pressure_.empty()) pressure_[c] *= inv_v;
    if (!energy_.empty()) energy_[c] *= inv_m;
    if (!sound_speed_.empty()) sound_speed_[c] *= inv_m;
    if (!burn_.empty()) burn_[c] *= inv_m;
    if (!material_.empty()) {
      // The material with the largest volume share (mass would favour dense products).
      double best = 0.0;
      material_[c] = -1.0;
      for (std::size_t r = 0; r < material_names_.size(); ++r)
        if (material_volume_[r * cells + c] > best) {
          best = material_volume_[r * cells + c];
          material_[c] = static_cast<double>(r);
        }
    }
    if (!material_volume_.empty())
      for (std::size_t r = 0; r < material_names_.size(); ++r)
        material_volume_[r * cells + c] *= inv_v;
  }
}

std::vector<io::FieldView> CellFields::views(const MpmSolver& solver) {
  bin(solver);
  const std::size_t cells = grid_.cell_count();
  std::vector<io::FieldView> out;
  for (const config::Field f : fields_) {
    switch (f) {
      case config::Field::density:
        out.push_back({"density", "kg/m^3", {density_}});
        break;
      case config::Field::velocity:
        out.push_back({"velocity", "m/s", {velocity_[0], velocity_[1], velocity_[2]}});
        break;
      case config::Field::pressure:
        out.push_back({"pressure", "Pa", {pressure_}});
        break;
      case config::Field::specific_internal_energy:
        out.push_back({"specific_internal_energy", "J/kg", {energy_}});
        break;
      case config::Field::sound_speed:
        out.push_back({"sound_speed", "m/s", {sound_speed_}});
        break;
      case config::Field::burn_fraction:
        out.push_back({"burn_fraction", "", {burn_}});
        break;
      case config::Field::material:
        out.push_back({"material", "", {material_}});
        break;
      case config::Field::volume_fraction:
        for (std::size_t r = 0; r < material_names_.size(); ++r)
          out.push_back({"volume_fraction_" + material_names_[r],
                         "",
                         {std::span<const double>(material_volume_).subspan(r * cells, cells)}});
        break;
    }
  }
  return out;
}

GaugeCells::GaugeCells(const grid::UniformGrid& grid, std::span<const grid::Vec3> positions)
    : grid_(grid) {
  for (const auto& x : positions) cell_.push_back(cell_holding(grid_, x[0], x[1], x[2]));
  mass_.resize(cell_.size());
  volume_.resize(cell_.size());
  pressure_.resize(cell_.size());
  momentum_.resize(3 * cell_.size());
}

void GaugeCells::sample(const ParticleSet& ps, std::span<double> out) {
  std::fill(mass_.begin(), mass_.end(), 0.0);
  std::fill(volume_.begin(), volume_.end(), 0.0);
  std::fill(pressure_.begin(), pressure_.end(), 0.0);
  std::fill(momentum_.begin(), momentum_.end(), 0.0);
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const std::size_t c =
        cell_holding(grid_, ps.position[0][p], ps.position[1][p], ps.position[2][p]);
    for (std::size_t g = 0; g < cell_.size(); ++g) {
      if (cell_[g] != c) continue;
      const double v = ps.mass[p] / ps.density[p];
      mass_[g] += ps.mass[p];
      volume_[g] += v;
      pressure_[g] += v * ps.pressure[p];
      for (int a = 0; a < 3; ++a) momentum_[3 * g + a] += ps.mass[p] * ps.velocity[a][p];
    }
  }
  for (std::size_t g = 0; g < cell_.size(); ++g) {
    const double inv_m = mass_[g] > 0.0 ? 1.0 / mass_[g] : 0.0;
    out[5 * g + 0] = mass_[g] / grid_.cell_volume();
    out[5 * g + 1] = volume_[g] > 0.0 ? pressure_[g] / volume_[g] : 0.0;
    for (int a = 0; a < 3; ++a) out[5 * g + 2 + a] = momentum_[3 * g + a] * inv_m;
  }
}

}  // namespace mpfd::mpm
