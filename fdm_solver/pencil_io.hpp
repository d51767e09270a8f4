#pragma once
// Moving one line of cells between the state and a Pencil: gather (rotating
// momenta so the sweep axis is "normal", and making the kGhost ghost cells
// at each domain face from its boundary condition) and scatter back.
// Boundary conditions, per face:
//   outflow   zero gradient: every ghost copies the adjacent cell (transmissive);
//   wall      mirror image with the normal momentum reversed (reflective);
//   symmetry  the same mirror: for inviscid flow a symmetry plane is a wall.

#include <array>
#include <cstddef>

#include "common/config/scene.hpp"
#include "fdm_solver/euler_state.hpp"
#include "fdm_solver/pencil.hpp"

namespace mpfd::fdm {

/// Ghost cells per pencil end. A sweep reads i-3 ... i+3: the two-step
/// Lax-Wendroff update reaches one cell, the artificial viscosity (2-56) one
/// more, and its face switch max(theta_i, theta_i+1) (2-57) one more.
inline constexpr std::size_t kGhost = 3;

/// Where a pencil lies: its axis, and the state index of its first cell.
struct PencilLine {
  int axis;
  std::size_t start;
  std::size_t stride;
  std::size_t length;  ///< interior cells
};

/// The boundary condition of the two faces normal to an axis.
struct AxisBoundaries {
  config::BoundaryKind lower;
  config::BoundaryKind upper;
};

/// Copies the line's cells [first, last) plus kGhost neighbours on each side
/// (made from the boundary conditions where the line ends) into the pencil;
/// pencil position = cell position + kGhost.
void gather(const EulerState& state, const PencilLine& line, AxisBoundaries faces,
            std::size_t first, std::size_t last, Pencil& pencil);

/// Copies the pencil's cells [first, last) back into the state.
void scatter(const Pencil& pencil, const PencilLine& line, std::size_t first, std::size_t last,
             EulerState& state);

}  // namespace mpfd::fdm
