#pragma once
// One line of cells along the sweep axis, gathered into contiguous buffers so
// that the sweep's inner loops are unit-stride and vectorise. Variables are
// rotated so that "normal" momentum is along the sweep axis. One Pencil per
// thread, sized once for the longest axis: no allocation inside a step.

#include <array>
#include <cstdint>
#include <vector>

namespace mpfd::fdm {

/// Rotated conserved variables: density, normal momentum, the two tangential
/// momenta, total energy.
enum PencilVariable : std::size_t { kRho = 0, kMn, kMt1, kMt2, kE };

struct Pencil {
  std::array<std::vector<double>, 5> u;          ///< state; updated in place
  std::array<std::vector<double>, 5> ubar;       ///< state plus artificial viscosity, T (2-56)
  std::array<std::vector<double>, 5> flux;       ///< flux of ubar, then of the half-step state
  std::array<std::vector<double>, 5> half;       ///< Richtmyer half-step state at face i+1/2
  std::array<std::vector<double>, 5> diffusion;  ///< viscous exchange across face i+1/2
  std::vector<double> pressure;
  std::vector<double> sound_speed;
  std::vector<double> theta;  ///< shock switch, T (2-57)
  std::vector<std::uint8_t> material;

  void resize(std::size_t length);
};

}  // namespace mpfd::fdm
