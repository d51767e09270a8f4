#include "coupler/handoff/mpm_to_fdm.hpp"

#include <string>
#include <utility>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/core/require.hpp"
#include "coupler/handoff/grid_stencil.hpp"

namespace mpfd::coupler::handoff {
namespace {

grid::CellLocation locate_particle(const grid::UniformGrid& grid, const ParticleView& particles,
                                   std::size_t p) {
  const grid::Vec3 x{particles.position[0][p], particles.position[1][p], particles.position[2][p]};
  const auto where = grid.locate(x);
  if (!where)
    throw Error("mpm_to_fdm: particle " + std::to_string(p) + " at (" + shortest_text(x[0]) + ", " +
                shortest_text(x[1]) + ", " + shortest_text(x[2]) + ") must lie inside the grid");
  return *where;
}

}  // namespace

NodalFields scatter_to_nodes(const grid::UniformGrid& grid, const ParticleView& particles) {
  check_sizes(particles);
  const std::size_t nodes = grid.node_count();
  NodalFields out;
  out.mass.assign(nodes, 0.0);
  for (auto& p : out.momentum) p.assign(nodes, 0.0);
  out.kinetic_energy.assign(nodes, 0.0);
  const int corners = corner_count(grid);
  // Serial: a one-off handoff, and the sums stay deterministic.
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const grid::CellLocation where = locate_particle(grid, particles, p);
    const double m = particles.mass[p];
    const std::array<double, 3> v{particles.velocity[0][p], particles.velocity[1][p],
                                  particles.velocity[2][p]};
    const double kinetic = 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int corner = 0; corner < corners; ++corner) {
      const double n = corner_weight(grid, where.local, corner);
      const std::size_t node = grid.node_index(corner_node(grid, where.cell, corner));
      out.mass[node] += n * m;                                            // T (2-12)
      for (int a = 0; a < 3; ++a) out.momentum[a][node] += n * m * v[a];  // T (2-9)
      out.kinetic_energy[node] += n * kinetic;
    }
  }
  return out;
}

std::vector<double> cell_internal_energy(const grid::UniformGrid& grid,
                                         const ParticleView& particles) {
  check_sizes(particles);
  std::vector<double> internal(grid.cell_count(), 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const grid::CellLocation where = locate_particle(grid, particles, p);
    internal[grid.cell_index(where.cell)] += particles.internal_energy[p];  // T (3-5)
  }
  return internal;
}

TracerPoints tracers_from_particles(const ParticleView& particles) {
  check_sizes(particles);
  TracerPoints tracers;
  tracers.material.assign(particles.material.begin(), particles.material.end());
  for (int a = 0; a < 3; ++a)
    tracers.position[a].assign(particles.position[a].begin(), particles.position[a].end());
  return tracers;
}

FdmCells cells_from_nodes(const grid::UniformGrid& grid, const NodalFields& nodes,
                          std::span<const double> cell_internal_energy) {
  const std::size_t node_count = grid.node_count();
  const std::size_t cells = grid.cell_count();
  const bool with_kinetic = !nodes.kinetic_energy.empty();
  const auto expect = [](std::size_t got, std::size_t want, const char* name) {
    if (got != want)
      throw Error(std::string("mpm_to_fdm: ") + name + " must have " + std::to_string(want) +
                  " entries, got " + std::to_string(got));
  };
  expect(nodes.mass.size(), node_count, "node_mass");
  for (const auto& p : nodes.momentum) expect(p.size(), node_count, "node_momentum");
  if (with_kinetic) expect(nodes.kinetic_energy.size(), node_count, "node_kinetic_energy");
  expect(cell_internal_energy.size(), cells, "cell_internal_energy");
  const double volume = grid.cell_volume();

  FdmCells out;
  out.cells.assign(cells);
  std::vector<double> heat(cells, 0.0);
  const int corners = corner_count(grid);
  parallel_for(cells, [&](std::size_t c) {
    const grid::Index3 cell = grid.cell_of_index(c);
    double m = 0.0;
    std::array<double, 3> p{};
    double kinetic = 0.0;
    for (int corner = 0; corner < corners; ++corner) {
      const grid::Index3 node = corner_node(grid, cell, corner);
      const double share = node_to_cell_share(grid, node);
      const std::size_t i = grid.node_index(node);
      m += share * nodes.mass[i];                                        // T (3-3)
      for (int a = 0; a < 3; ++a) p[a] += share * nodes.momentum[a][i];  // T (3-4)
      if (with_kinetic) kinetic += share * nodes.kinetic_energy[i];
    }
    const double resolved = m > 0.0 ? 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / m : 0.0;
    if (!with_kinetic) kinetic = resolved;
    out.cells.density[c] = m / volume;                                         // T (3-6)
    for (int a = 0; a < 3; ++a) out.cells.momentum[a][c] = p[a] / volume;      // T (3-7)
    out.cells.total_energy[c] = (cell_internal_energy[c] + kinetic) / volume;  // T (3-8)
    heat[c] = kinetic - resolved;
  });
  for (const double h : heat) out.kinetic_to_internal += h;
  return out;
}

FdmStart mpm_to_fdm(const grid::UniformGrid& grid, const ParticleView& particles) {
  FdmCells cells = cells_from_nodes(grid, scatter_to_nodes(grid, particles),
                                    cell_internal_energy(grid, particles));
  return {std::move(cells.cells), tracers_from_particles(particles), cells.kinetic_to_internal};
}

}  // namespace mpfd::coupler::handoff
