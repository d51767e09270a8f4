#pragma once
// Moving a block of neighbouring lines of cells between the state and a
// Pencil: gather (rotating momenta so the sweep axis is "normal", and making
// the kGhost ghost cells at each domain face from its boundary condition)
// and scatter back. Boundary conditions, per face:
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

/// Where a block of lines lies in the state.
struct PencilBlock {
  int axis;                 ///< the sweep axis
  std::size_t start;        ///< state index of the first cell of lane 0
  std::size_t stride;       ///< between neighbours along the axis
  std::size_t length;       ///< interior cells along the axis
  std::size_t lane_stride;  ///< between neighbouring lanes
  std::size_t lanes;        ///< 1 ... kMaxLanes
};

/// The boundary condition of the two faces normal to an axis.
struct AxisBoundaries {
  config::BoundaryKind lower;
  config::BoundaryKind upper;
};

/// Copies cells [first, last) of every lane plus kGhost neighbours on each
/// side (made from the boundary conditions where the lines end) into the
/// pencil; pencil position = cell position + kGhost.
void gather(const EulerState& state, const PencilBlock& block, AxisBoundaries faces,
            std::size_t first, std::size_t last, Pencil& pencil);

/// Copies the pencil's cells [first, last) of every lane back into the state.
void scatter(const Pencil& pencil, const PencilBlock& block, std::size_t first, std::size_t last,
             EulerState& state);

}  // namespace mpfd::fdm
