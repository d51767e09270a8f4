#pragma once
// Tracer advection, T (3-13): X^{n+1} = X^n + v^n(X^n) dt (forward Euler),
// with v^n interpolated from the cell-centre velocities of time level n by
// quadratic_stencil.hpp, T (3-9)-(3-12). Only active axes move.
// At the domain faces: a tracer that crosses an outflow face is removed (the
// material leaves with the flux); one that crosses a wall or symmetry face is
// mirrored back inside (clamped inside if it moved farther than the domain).

#include <array>
#include <cstddef>

#include "common/grid/uniform_grid.hpp"
#include "fdm_solver/tracer/quadratic_stencil.hpp"
#include "fdm_solver/tracer/tracer_set.hpp"

namespace mpfd::fdm {

/// What a tracer meets at a domain face: outflow removes it, reflect mirrors
/// it (scene boundary kinds wall and symmetry).
enum class TracerFace { outflow, reflect };

/// Per-face behaviour indexed like config::Face: x_lower, x_upper, y_lower,
/// y_upper, z_lower, z_upper.
using TracerBoundaries = std::array<TracerFace, 6>;

struct AdvectionReport {
  std::size_t removed = 0;       ///< tracers that left through an outflow face this step
  double max_cells_moved = 0.0;  ///< the largest |u_a dt| / dx_a of any tracer and axis [cells]
};

/// Moves every tracer by one step dt [s] >= 0 with the cell-centre velocity
/// field v of time level n; removes (by compaction, no allocation) those that
/// leave through an outflow face. Throws mpfd::Error if an active velocity
/// component's size is not the cell count, dt is negative or not finite, or a
/// tracer reaches a non-finite position (a NaN or inf velocity).
AdvectionReport advect_tracers(const grid::UniformGrid& grid, const VelocityView& v, double dt,
                               const TracerBoundaries& faces, TracerSet& tracers);

}  // namespace mpfd::fdm
