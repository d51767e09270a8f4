#include "fdm_solver/tracer/material_states.hpp"

#include <array>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "fdm_solver/tracer/energy_split.hpp"

namespace mpfd::fdm {
namespace {

/// The two materials of a mixed cell (the first two with theta > 0).
std::array<int, 2> pair_of(const MaterialMap& map, std::size_t cell) {
  std::array<int, 2> pair{-1, -1};
  int found = 0;
  for (int r = 0; r < map.material_count && found < 2; ++r)
    if (map.volume_fraction(cell, r) > 0.0) pair[found++] = r;
  return pair;
}

/// e_r for material r new to `cell`: mean over the face neighbours that held r.
double newcomer_energy(const grid::UniformGrid& grid, const MaterialMap& previous,
                       const MaterialStates& states, std::size_t cell, int r) {
  const grid::Index3 ijk = grid.cell_of_index(cell);
  double sum = 0.0;
  int count = 0;
  for (int a = 0; a < 3; ++a)
    for (const int d : {-1, 1}) {
      grid::Index3 nb = ijk;
      nb[a] += d;
      if (nb[a] < 0 || nb[a] >= grid.cells()[a]) continue;
      const std::size_t n = grid.cell_index(nb);
      if (previous.volume_fraction(n, r) <= 0.0) continue;
      sum += states.energy[states.at(r, n)];
      ++count;
    }
  return count > 0 ? sum / count : states.cell_energy[cell];
}

void check_sizes(std::size_t cells, std::span<const eos::AnyEos> eos, const MaterialMap& previous,
                 const MaterialMap& current, std::size_t rho, std::size_t e, std::size_t p) {
  const bool ok = previous.cell_count() == cells && current.cell_count() == cells && rho == cells &&
                  e == cells && p == cells &&
                  static_cast<std::size_t>(current.material_count) <= eos.size();
  if (!ok)
    throw Error("cell pressure update: the grid has " + std::to_string(cells) +
                " cells; got material maps of " + std::to_string(previous.cell_count()) + " and " +
                std::to_string(current.cell_count()) + ", density " + std::to_string(rho) +
                ", energy " + std::to_string(e) + ", pressure " + std::to_string(p) + ", and " +
                std::to_string(eos.size()) + " equations of state for " +
                std::to_string(current.material_count) + " materials");
}

}  // namespace

MaterialStates::MaterialStates(const MaterialMap& map, std::span<const double> rho,
                               std::span<const double> e)
    : cell_count(map.cell_count()),
      energy(map.theta.size(), 0.0),
      density(map.theta.size(), 0.0),
      cell_energy(e.begin(), e.end()),
      status(map.cell_count(), ClosureStatus::single_material) {
  if (rho.size() != cell_count || e.size() != cell_count)
    throw Error("material states: need " + std::to_string(cell_count) +
                " cell densities and energies, got " + std::to_string(rho.size()) + " and " +
                std::to_string(e.size()));
  for (int r = 0; r < map.material_count; ++r)
    for (std::size_t c = 0; c < cell_count; ++c)
      if (map.volume_fraction(c, r) > 0.0) {
        energy[at(r, c)] = e[c];
        density[at(r, c)] = rho[c];
      }
}

ClosureReport closure_report(const MaterialStates& states) {
  const auto count = [&](ClosureStatus which) {
    return parallel_sum(states.cell_count, [&](std::size_t c) -> std::size_t {
      return states.status[c] == which ? 1 : 0;
    });
  };
  return {states.cell_count - count(ClosureStatus::single_material),
          count(ClosureStatus::iteration_limit), count(ClosureStatus::fallback)};
}

ClosureReport update_cell_pressure(const grid::UniformGrid& grid, std::span<const eos::AnyEos> eos,
                                   const MaterialMap& previous, const MaterialMap& current,
                                   std::span<const double> rho, std::span<const double> e,
                                   MaterialStates& states, std::span<double> pressure) {
  const std::size_t cells = grid.cell_count();
  check_sizes(cells, eos, previous, current, rho.size(), e.size(), pressure.size());
  // Reads e_r only where r was present before, writes only where it was not.
  parallel_for(cells, [&](std::size_t c) {
    if (!current.is_mixed(c)) return;
    for (const int r : pair_of(current, c))
      if (previous.volume_fraction(c, r) <= 0.0)
        states.energy[states.at(r, c)] = newcomer_energy(grid, previous, states, c, r);
  });
  parallel_for(cells, [&](std::size_t c) {
    const int m = current.material[c];
    if (m != kMixedCell) {
      pressure[c] = eos::pressure(eos[static_cast<std::size_t>(m)], rho[c], e[c]);
      states.energy[states.at(m, c)] = e[c];
      states.density[states.at(m, c)] = rho[c];
      states.cell_energy[c] = e[c];
      states.status[c] = ClosureStatus::single_material;
      return;
    }
    const auto [a, b] = pair_of(current, c);
    const double theta_a = current.volume_fraction(c, a);
    const double theta_b = current.volume_fraction(c, b);
    const double increment = e[c] - states.cell_energy[c];
    const MixedCellInput in{
        .rho_c = rho[c],
        .theta1 = theta_a,
        .e1 = split_energy_increment(states.energy[states.at(a, c)], theta_a, increment),
        .e2 = split_energy_increment(states.energy[states.at(b, c)], theta_b, increment),
        .cell_energy = e[c]};
    const MixedCellState s =
        close_mixed_cell(eos[static_cast<std::size_t>(a)], eos[static_cast<std::size_t>(b)], in);
    pressure[c] = s.pressure;
    states.energy[states.at(a, c)] = s.e1;
    states.energy[states.at(b, c)] = s.e2;
    states.density[states.at(a, c)] = s.rho1;
    states.density[states.at(b, c)] = s.rho2;
    states.cell_energy[c] = e[c];
    states.status[c] = s.status;
  });
  return closure_report(states);
}

}  // namespace mpfd::fdm
