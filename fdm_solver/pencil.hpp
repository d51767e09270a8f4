#pragma once
// A block of up to kMaxLanes neighbouring lines of cells along the sweep axis,
// gathered into contiguous buffers interleaved by lane: value of lane w at
// position i is at [i * lanes + w]. Every operation of a sweep is elementwise
// along the line with neighbours at i +- 1, so it runs on all lanes at once
// with neighbours at +- lanes, and the inner loops are unit-stride whatever
// the sweep axis. Variables are rotated so that "normal" momentum is along
// the sweep axis. One Pencil per thread, sized once: no allocation in a step.

#include <array>
#include <cstdint>
#include <vector>

namespace mpfd::fdm {

/// Rotated conserved variables: density, normal momentum, the two tangential
/// momenta, total energy.
enum PencilVariable : std::size_t { kRho = 0, kMn, kMt1, kMt2, kE };

/// Lanes per block for sweeps across the x-rows: 16 doubles (two cache lines)
/// per row and position. Measured on the 128^3 blast: 8, 16 and 32 lanes are
/// within 3 % of each other; 16 was the best on 1 and 2 threads.
inline constexpr std::size_t kMaxLanes = 16;

struct Pencil {
  std::array<std::vector<double>, 5> u;          ///< state at the start of the sweep
  std::array<std::vector<double>, 5> u_new;      ///< state at its end
  std::array<std::vector<double>, 5> ubar;       ///< state plus artificial viscosity, T (2-56)
  std::array<std::vector<double>, 5> flux_bar;   ///< flux of ubar
  std::array<std::vector<double>, 5> flux;       ///< flux of the half-step state at face i+1/2
  std::array<std::vector<double>, 5> diffusion;  ///< viscous exchange across face i+1/2
  std::vector<double> pressure;                  ///< of u
  std::vector<double> sound_speed;               ///< of u
  std::vector<double> pressure_bar;              ///< of ubar
  std::vector<double> theta;                     ///< shock switch, T (2-57)
  std::vector<std::uint8_t> material;
  std::vector<double> mix_gamma;  ///< stiffened-gas gamma where material is kMixedMaterial
  std::vector<double> mix_pinf;   ///< stiffened-gas pi [Pa], same

  /// Room for `length` positions of kMaxLanes lanes.
  void resize(std::size_t length);
};

}  // namespace mpfd::fdm
