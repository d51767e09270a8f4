#include "coupler/handoff/material_start.hpp"

#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handoff {
namespace {

void require_size(std::size_t got, std::size_t want, const char* name) {
  if (got != want)
    throw Error(std::string("material start: ") + name + " must have " + std::to_string(want) +
                " entries, got " + std::to_string(got));
}

enum class CellKind { empty, single, mixed, mixed_fallback };

}  // namespace

MaterialSums::MaterialSums(std::size_t cells, int materials) : material_count(materials) {
  if (materials < 1)
    throw Error("material start: material_count must be >= 1, got " + std::to_string(materials));
  const std::size_t rows = cells * static_cast<std::size_t>(materials);
  mass.assign(rows, 0.0);
  volume.assign(rows, 0.0);
  energy.assign(rows, 0.0);
  contributors.assign(rows, 0);
}

MaterialSums particle_material_sums(const grid::UniformGrid& grid, const ParticleView& particles,
                                    std::span<const double> volume, int materials) {
  check_sizes(particles);
  require_size(volume.size(), particles.size(), "particle volume");
  MaterialSums sums(grid.cell_count(), materials);
  // Serial: a one-off handoff, and the sums stay deterministic.
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const grid::Vec3 x{particles.position[0][p], particles.position[1][p],
                       particles.position[2][p]};
    const auto where = grid.locate(x);
    if (!where)
      throw Error("material start: particle " + std::to_string(p) + " at (" + shortest_text(x[0]) +
                  ", " + shortest_text(x[1]) + ", " + shortest_text(x[2]) +
                  ") m must lie inside the grid");
    const int r = particles.material[p];
    if (r < 0 || r >= materials)
      throw Error("material start: particle " + std::to_string(p) + " has material " +
                  std::to_string(r) + ", outside [0, " + std::to_string(materials) + ")");
    const std::size_t row = grid.cell_index(where->cell) * static_cast<std::size_t>(materials) +
                            static_cast<std::size_t>(r);
    sums.mass[row] += particles.mass[p];
    sums.volume[row] += volume[p];
    sums.energy[row] += particles.internal_energy[p];  // extensive, T (3-5)
    ++sums.contributors[row];
  }
  return sums;
}

MaterialStart material_start(const grid::UniformGrid& grid, const ParticleView& particles,
                             std::span<const double> volume, const ConservedView& cells,
                             int material_count) {
  return material_start(grid, particle_material_sums(grid, particles, volume, material_count),
                        cells);
}

MaterialStart material_start(const grid::UniformGrid& grid, MaterialSums sums,
                             const ConservedView& cells) {
  check_sizes(cells, grid.cell_count());
  const int material_count = sums.material_count;
  const auto materials = static_cast<std::size_t>(material_count);
  const std::size_t n = grid.cell_count();
  for (const auto* values : {&sums.mass, &sums.volume, &sums.energy})
    require_size(values->size(), n * materials, "material sums");
  require_size(sums.contributors.size(), n * materials, "material contributors");
  const double cell_volume = grid.cell_volume();
  // Fitted in place: each row r of a cell is read (and summed over the cell) before
  // it is written, and depends only on itself and those sums; no second set of rows
  // at the handoff's memory peak.
  MaterialStart out;
  out.material_count = material_count;
  out.volume_fraction = std::move(sums.volume);
  out.density = std::move(sums.mass);
  out.energy = std::move(sums.energy);
  const std::vector<int>& contributors = sums.contributors;
  std::vector<double>& volume = out.volume_fraction;  // V_r, then theta_r
  std::vector<double>& mass = out.density;            // m_r, then rho_r
  std::vector<double>& energy = out.energy;           // E_r, then e_r
  std::vector<CellKind> kind(n, CellKind::empty);
  parallel_for(n, [&](std::size_t c) {
    const std::size_t row = c * materials;
    const auto set_rows = [&](auto value_of) {  // every row of the cell: (theta, rho, e)
      for (std::size_t r = 0; r < materials; ++r) {
        const auto [theta, rho, e] = value_of(r);
        volume[row + r] = theta;
        mass[row + r] = rho;
        energy[row + r] = e;
      }
    };
    const auto none = [](std::size_t) { return std::array<double, 3>{0.0, 0.0, 0.0}; };
    double m_sum = 0.0, v_sum = 0.0, e_sum = 0.0;
    int present = 0;
    bool usable = true;
    for (std::size_t r = 0; r < materials; ++r) {
      if (contributors[row + r] == 0) continue;
      ++present;
      m_sum += mass[row + r];
      v_sum += volume[row + r];
      e_sum += energy[row + r];
      usable = usable && mass[row + r] > 0.0 && volume[row + r] > 0.0 && energy[row + r] > 0.0 &&
               std::isfinite(mass[row + r]) && std::isfinite(volume[row + r]) &&
               std::isfinite(energy[row + r]);
    }
    if (present == 0) return set_rows(none);
    const double rho_c = cells.density[c];
    const double m_c = rho_c * cell_volume;
    const double mx = cells.momentum[0][c], my = cells.momentum[1][c], mz = cells.momentum[2][c];
    // e_c as the FDM reads it from rho, rho v, E (fdm_solver/euler_state.hpp).
    const double e_c =
        rho_c > 0.0 ? (cells.total_energy[c] - 0.5 * (mx * mx + my * my + mz * mz) / rho_c) / rho_c
                    : 0.0;
    if (present == 1) {
      // The FDM does not use these rows, but refuses a negative or non-finite energy
      // in them: a round-off-negative e_c leaves the row at 0 (no state).
      if (!(e_c >= 0.0 && std::isfinite(e_c))) return set_rows(none);
      set_rows([&](std::size_t r) {
        return contributors[row + r] > 0 ? std::array<double, 3>{1.0, rho_c, e_c}
                                         : std::array<double, 3>{0.0, 0.0, 0.0};
      });
      kind[c] = CellKind::single;
      return;
    }
    const double u_c = m_c * e_c;  // U_c = E_c V_c - |p_c|^2 / (2 m_c)
    if (!(usable && m_c > 0.0 && u_c > 0.0 && std::isfinite(u_c))) {
      set_rows(none);
      kind[c] = CellKind::mixed_fallback;
      return;
    }
    const double k = u_c * m_sum / (m_c * e_sum);  // sum_r m_r' e_r = U_c
    set_rows([&](std::size_t r) {
      if (contributors[row + r] == 0) return std::array<double, 3>{0.0, 0.0, 0.0};
      const double theta = volume[row + r] / v_sum;                     // T (3-23)
      const double m_r = mass[row + r] / m_sum * m_c;                   // scaled to m_c, T (3-3)
      return std::array<double, 3>{theta, m_r / (theta * cell_volume),  // T (3-28) holds
                                   k * energy[row + r] / mass[row + r]};
    });
    kind[c] = CellKind::mixed;
  });
  for (const CellKind k : kind) {
    out.mixed_cells += k == CellKind::mixed || k == CellKind::mixed_fallback ? 1 : 0;
    out.fallback_cells += k == CellKind::mixed_fallback ? 1 : 0;
    out.empty_cells += k == CellKind::empty ? 1 : 0;
  }
  return out;
}

}  // namespace mpfd::coupler::handoff
