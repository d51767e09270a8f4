#include "coupler/handshake/particle_removal.hpp"

#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"

namespace mpfd::coupler::handshake {

template <int Dim>
void locate_deposit_cells(std::span<const Vec<Dim>> position, const IndexBox<Dim>& deposit,
                          const CellGeometry<Dim>& geometry, std::span<std::size_t> cell) {
  deposit.check("deposit cells");
  geometry.check();
  require_length(cell.size(), position.size(), "removed particles", "cell");
  for (std::size_t p = 0; p < position.size(); ++p) {
    Index<Dim> index{};
    for (int a = 0; a < Dim; ++a)
      index[a] = static_cast<std::int64_t>(
          std::floor((position[p](a) - geometry.origin(a)) / geometry.spacing(a)));
    if (!deposit.contains(index)) {
      std::string where;
      for (int a = 0; a < Dim; ++a) where += (a > 0 ? ", " : "") + shortest_text(position[p](a));
      throw Error("removed particles: particle " + std::to_string(p) + " at (" + where +
                  ") m must lie in a cell of deposit_cells; it is outside that box");
    }
    cell[p] = deposit.flat(index);
  }
}

template <int Dim>
void particle_amounts(std::span<const double> mass, std::span<const Vec<Dim>> velocity,
                      std::span<const double> internal_energy, std::span<Vec<Dim>> momentum,
                      std::span<double> energy) {
  const std::size_t n = mass.size();
  require_length(velocity.size(), n, "removed particles", "velocity");
  require_length(internal_energy.size(), n, "removed particles", "internal_energy");
  require_length(momentum.size(), n, "removed particles", "momentum");
  require_length(energy.size(), n, "removed particles", "energy");
  for (std::size_t p = 0; p < n; ++p) {
    momentum[p] = mass[p] * velocity[p];                                         // T (4-20)
    energy[p] = internal_energy[p] + 0.5 * mass[p] * velocity[p].squaredNorm();  // T (4-21)
  }
}

template <int Dim>
void deposit(std::span<const double> mass, std::span<const Vec<Dim>> momentum,
             std::span<const double> energy, std::span<const std::size_t> cell, double cell_volume,
             const CellOutputs<Dim>& add) {
  const std::size_t n = mass.size();
  require_length(momentum.size(), n, "deposit", "momentum");
  require_length(energy.size(), n, "deposit", "energy");
  require_length(cell.size(), n, "deposit", "cell");
  require_lengths(add, add.size(), "deposit cells");
  require(cell_volume > 0, "deposit", "cell_volume", cell_volume, "> 0");
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t c = cell[i];
    if (c >= add.size())
      throw Error("deposit: amount " + std::to_string(i) + " names cell " + std::to_string(c) +
                  ", but deposit_cells has " + std::to_string(add.size()));
    add.rho[c] += mass[i] / cell_volume;           // T (4-19)
    add.momentum[c] += momentum[i] / cell_volume;  // T (4-20)
    add.energy[c] += energy[i] / cell_volume;      // T (4-21)
  }
}

#define MPFD_INSTANTIATE_REMOVAL(Dim)                                                        \
  template void locate_deposit_cells<Dim>(std::span<const Vec<Dim>>, const IndexBox<Dim>&,   \
                                          const CellGeometry<Dim>&, std::span<std::size_t>); \
  template void particle_amounts<Dim>(std::span<const double>, std::span<const Vec<Dim>>,    \
                                      std::span<const double>, std::span<Vec<Dim>>,          \
                                      std::span<double>);                                    \
  template void deposit<Dim>(std::span<const double>, std::span<const Vec<Dim>>,             \
                             std::span<const double>, std::span<const std::size_t>, double,  \
                             const CellOutputs<Dim>&);
MPFD_INSTANTIATE_REMOVAL(1)
MPFD_INSTANTIATE_REMOVAL(2)
MPFD_INSTANTIATE_REMOVAL(3)
#undef MPFD_INSTANTIATE_REMOVAL

}  // namespace mpfd::coupler::handshake
