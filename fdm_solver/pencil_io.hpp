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
#include <cstdint>
#include <optional>

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

/// Where a sweep reads and writes: the state, the block of lines in it and
/// the boundary conditions of the two faces it meets. `state` is read ahead of
/// the update and written behind it (other threads hold other lines).
struct BlockTransfer {
  EulerState& state;
  PencilBlock block;
  AxisBoundaries faces;
  std::size_t first;  ///< first updated cell along the axis
  std::size_t last;   ///< one past the last updated cell
  /// The material of every cell of the grid, if they share one (no mixed
  /// cells): the block's materials need not be gathered.
  std::optional<std::uint8_t> only_material;
  /// 0, or a cell in [first, last] whose lower face's crossing the sweep
  /// reports (EndFluxes::tapped): a coupling face (proto/README.md §14).
  std::size_t tap = 0;
};

/// Copies the material (and mixed cells' EOS) of cells [first - kGhost,
/// last + kGhost) of every lane into the pencil, ghosts made from the
/// boundary conditions where the lines end; pencil position = cell + kGhost.
void gather_materials(const BlockTransfer& t, Pencil& pencil);

/// Copies the state of pencil positions [from, to) into pencil.u, within the
/// stencil [first, last + 2 kGhost), making the ghosts of a domain face from
/// the cells the range has copied. Called with consecutive ranges from
/// `first`, so that each ghost's source is copied when it is made.
void gather_rows(const BlockTransfer& t, std::size_t from, std::size_t to, Pencil& pencil);

/// Makes the ghosts of the domain faces that t's stencil reaches again from
/// the cells in pencil.u (after they have changed).
void remake_ghosts(const BlockTransfer& t, Pencil& pencil);

/// Copies pencil.u_new at positions [from, to) (updated cells) back into the state.
void scatter_rows(const Pencil& pencil, const BlockTransfer& t, std::size_t from, std::size_t to);

}  // namespace mpfd::fdm
