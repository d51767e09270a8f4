#include "coupler/handoff/mpm_to_fdm.hpp"

#include <string>

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

FdmStart mpm_to_fdm(const grid::UniformGrid& grid, const NodalFields& nodes,
                    const ParticleView& particles) {
  check_sizes(particles);
  const std::size_t node_count = grid.node_count();
  if (nodes.mass.size() != node_count || nodes.kinetic_energy.size() != node_count ||
      nodes.momentum[0].size() != node_count || nodes.momentum[1].size() != node_count ||
      nodes.momentum[2].size() != node_count)
    throw Error("mpm_to_fdm: nodal fields must have " + std::to_string(node_count) +
                " entries (the grid's node count), got mass " + std::to_string(nodes.mass.size()));
  const std::size_t cells = grid.cell_count();
  const double volume = grid.cell_volume();

  std::vector<double> internal(cells, 0.0);
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const grid::CellLocation where = locate_particle(grid, particles, p);
    internal[grid.cell_index(where.cell)] += particles.internal_energy[p];  // T (3-5)
  }

  FdmStart out;
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
      kinetic += share * nodes.kinetic_energy[i];
    }
    out.cells.density[c] = m / volume;                                     // T (3-6)
    for (int a = 0; a < 3; ++a) out.cells.momentum[a][c] = p[a] / volume;  // T (3-7)
    out.cells.total_energy[c] = (internal[c] + kinetic) / volume;          // T (3-8)
    const double resolved = m > 0.0 ? 0.5 * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) / m : 0.0;
    heat[c] = kinetic - resolved;
  });
  for (const double h : heat) out.kinetic_to_internal += h;

  out.tracers.material.assign(particles.material.begin(), particles.material.end());
  for (int a = 0; a < 3; ++a)
    out.tracers.position[a].assign(particles.position[a].begin(), particles.position[a].end());
  return out;
}

FdmStart mpm_to_fdm(const grid::UniformGrid& grid, const ParticleView& particles) {
  return mpm_to_fdm(grid, scatter_to_nodes(grid, particles), particles);
}

}  // namespace mpfd::coupler::handoff
