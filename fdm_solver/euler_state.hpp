#pragma once
// The conserved state of the Euler equations, T (2-49), (2-50):
// U = [rho, rho u, rho v, rho w, E] at cell centres, E = rho (e + |u|^2 / 2),
// one contiguous array per variable (structure of arrays) in the grid's cell
// order (x fastest). Ghost cells are not stored: each sweep's pencil makes
// its own from the boundary conditions (pencil_io.hpp).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::fdm {

enum Variable : std::size_t { kDensity = 0, kMomentumX, kMomentumY, kMomentumZ, kEnergy };
inline constexpr std::size_t kVariables = 5;

struct EulerState {
  explicit EulerState(const grid::UniformGrid& g) : grid(g), material(g.cell_count(), 0) {
    for (auto& v : u) v.assign(g.cell_count(), 0.0);
  }

  grid::UniformGrid grid;
  std::array<std::vector<double>, kVariables> u;
  std::vector<std::uint8_t> material;  ///< index into the scene's materials, or kMixedMaterial
  /// Stiffened-gas EOS of mixed cells (mixture_eos.hpp); empty in a scene
  /// with one material.
  std::vector<double> mix_gamma;
  std::vector<double> mix_pinf;
};

/// Specific internal energy e = E/rho - |u|^2/2 of cell c [J/kg].
[[nodiscard]] inline double specific_internal_energy(const EulerState& s, std::size_t c) {
  const double rho = s.u[kDensity][c];
  const double mx = s.u[kMomentumX][c], my = s.u[kMomentumY][c], mz = s.u[kMomentumZ][c];
  return (s.u[kEnergy][c] - 0.5 * (mx * mx + my * my + mz * mz) / rho) / rho;
}

}  // namespace mpfd::fdm
