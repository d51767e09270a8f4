#include "coupler/handshake/ghost_cells.hpp"

#include <algorithm>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handshake {

template <int Dim>
std::vector<std::size_t> corner_nodes(const IndexBox<Dim>& cells, const IndexBox<Dim>& nodes) {
  cells.check("ghost cells");
  nodes.check("ghost nodes");
  std::vector<std::size_t> corners(cells.count() * kCorners<Dim>);
  for (std::size_t c = 0; c < cells.count(); ++c) {
    const Index<Dim> cell = cells.at(c);
    for (int q = 0; q < kCorners<Dim>; ++q) {
      Index<Dim> node = cell;
      for (int a = 0; a < Dim; ++a) node[a] += (q >> a) & 1;
      if (!nodes.contains(node))
        throw Error("ghost nodes: the node box must hold every corner of the ghost cells; cell " +
                    std::to_string(c) + " has corner " + std::to_string(q) + " outside it");
      corners[c * kCorners<Dim> + q] = nodes.flat(node);
    }
  }
  return corners;
}

template <int Dim>
std::vector<double> corner_support(const IndexBox<Dim>& cells, const Index<Dim>& domain_cells) {
  cells.check("ghost cells");
  std::vector<double> support(cells.count());
  for (std::size_t c = 0; c < cells.count(); ++c) {
    const Index<Dim> cell = cells.at(c);
    double sum = 0;
    for (int q = 0; q < kCorners<Dim>; ++q) {
      double share = 1;  // of the node's volume V_c inside the domain
      for (int a = 0; a < Dim; ++a) {
        const std::int64_t node = cell[a] + ((q >> a) & 1);
        if (node == 0 || node == domain_cells[a]) share *= 0.5;
      }
      sum += share / kCorners<Dim>;
    }
    support[c] = sum;
  }
  return support;
}

void sum_internal_energy(std::span<const std::size_t> cell_of_particle,
                         std::span<const double> internal_energy, std::span<double> cell_energy) {
  require_length(internal_energy.size(), cell_of_particle.size(), "T (4-3) particles",
                 "internal_energy");
  for (double& e : cell_energy) e = 0;
  for (std::size_t p = 0; p < cell_of_particle.size(); ++p) {
    const std::size_t c = cell_of_particle[p];
    if (c >= cell_energy.size())
      throw Error("T (4-3) particles: particle " + std::to_string(p) + " names cell " +
                  std::to_string(c) + ", but there are " + std::to_string(cell_energy.size()));
    cell_energy[c] += internal_energy[p];  // T (4-3)
  }
}

template <int Dim>
std::optional<std::size_t> fill_ghost_cells(const GhostSource<Dim>& source,
                                            std::span<const std::size_t> corners,
                                            std::span<const double> support, double cell_volume,
                                            const CellOutputs<Dim>& ghost) {
  const std::size_t n = ghost.size();
  require_lengths(ghost, n, "ghost cells");
  require_length(source.cell_internal_energy.size(), n, "ghost cells", "internal_energy");
  require_length(corners.size(), n * kCorners<Dim>, "ghost cells", "corner list");
  require_length(support.size(), n, "ghost cells", "corner support");
  require_length(source.node_momentum.size(), source.node_mass.size(), "ghost nodes", "momentum");
  require(cell_volume > 0, "ghost cells", "cell_volume", cell_volume, "> 0");
  for (const std::size_t node : corners)
    if (node >= source.node_mass.size())
      throw Error("ghost cells: corner node " + std::to_string(node) + " is outside the " +
                  std::to_string(source.node_mass.size()) + " ghost nodes");
  constexpr double weight = 1.0 / kCorners<Dim>;  // N_Ic at the cell centre
  const std::size_t bad = parallel_sum(n, [&](std::size_t c) -> std::size_t {
    double mass = 0;
    Vec<Dim> momentum = Vec<Dim>::Zero();
    for (int q = 0; q < kCorners<Dim>; ++q) {
      const std::size_t node = corners[c * kCorners<Dim> + q];
      mass += weight * source.node_mass[node];          // T (4-1)
      momentum += weight * source.node_momentum[node];  // T (4-2)
    }
    if (!(mass > 0)) {
      ghost.rho[c] = 0;  // marks the cell for the search below
      return 1;
    }
    const double volume = support[c] * cell_volume;  // the corner nodes' volume in the domain
    ghost.rho[c] = mass / volume;                    // T (4-4)
    ghost.momentum[c] = momentum / volume;           // T (4-5): ρ_c p_c / m_c
    ghost.energy[c] =
        (source.cell_internal_energy[c] + 0.5 * momentum.squaredNorm() / mass) / volume;  // T (4-6)
    return 0;
  });
  if (bad == 0) return std::nullopt;
  // A filled cell has rho > 0 (mass and volume > 0): the first cell without is the one to name.
  const auto first =
      std::find_if(ghost.rho.begin(), ghost.rho.end(), [](double rho) { return !(rho > 0); });
  return static_cast<std::size_t>(first - ghost.rho.begin());
}

#define MPFD_INSTANTIATE_GHOST(Dim)                                                                \
  template std::vector<std::size_t> corner_nodes<Dim>(const IndexBox<Dim>&, const IndexBox<Dim>&); \
  template std::vector<double> corner_support<Dim>(const IndexBox<Dim>&, const Index<Dim>&);       \
  template std::optional<std::size_t> fill_ghost_cells<Dim>(                                       \
      const GhostSource<Dim>&, std::span<const std::size_t>, std::span<const double>, double,      \
      const CellOutputs<Dim>&);
MPFD_INSTANTIATE_GHOST(1)
MPFD_INSTANTIATE_GHOST(2)
MPFD_INSTANTIATE_GHOST(3)
#undef MPFD_INSTANTIATE_GHOST

}  // namespace mpfd::coupler::handshake
