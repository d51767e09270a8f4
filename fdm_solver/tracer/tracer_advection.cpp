#include "fdm_solver/tracer/tracer_advection.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/parallel_for.hpp"

namespace mpfd::fdm {
namespace {

constexpr const char* kAxisName[3] = {"x", "y", "z"};

/// Position along one axis after the domain faces [lo, hi) had their say, or
/// NaN if the tracer leaves through an outflow face.
double apply_faces(double x, double lo, double hi, TracerFace lower, TracerFace upper) {
  if (x < lo) {
    if (lower == TracerFace::outflow) return std::nan("");
    x = lo + (lo - x);  // mirror at the lower face
  } else if (x >= hi) {
    if (upper == TracerFace::outflow) return std::nan("");
    x = hi - (x - hi);  // mirror at the upper face
  }
  return std::clamp(x, lo, std::nextafter(hi, lo));  // moved farther than the domain
}

void check_inputs(const grid::UniformGrid& grid, const VelocityView& v, double dt) {
  if (!(dt >= 0.0) || !std::isfinite(dt))
    throw Error("tracer advection: the time step must be finite and >= 0 s, got " +
                std::to_string(dt));
  for (int a = 0; a < 3; ++a)
    if (grid.is_active(a) && v.component[a].size() != grid.cell_count())
      throw Error(std::string("tracer advection: velocity component ") + kAxisName[a] + " has " +
                  std::to_string(v.component[a].size()) + " values, the grid " +
                  std::to_string(grid.cell_count()) + " cells");
}

}  // namespace

AdvectionReport advect_tracers(const grid::UniformGrid& grid, const VelocityView& v, double dt,
                               const TracerBoundaries& faces, TracerSet& tracers) {
  check_inputs(grid, v, dt);
  const grid::Vec3 lo = grid.origin();
  const grid::Vec3 hi = grid.upper();
  const grid::Vec3 dx = grid.spacing();
  // Moves tracer t; returns 1 if it leaves (or is lost), and its largest move in cells.
  const auto move = [&](std::size_t t, double& cells_moved) -> std::size_t {
    grid::Vec3 x{tracers.position[0][t], tracers.position[1][t], tracers.position[2][t]};
    const grid::Vec3 u = interpolate_velocity(grid, v, x);  // T (3-10)-(3-12)
    for (int a = 0; a < 3; ++a) {
      if (!grid.is_active(a)) continue;
      const double moved = x[a] + u[a] * dt;  // T (3-13)
      if (!std::isfinite(moved)) {
        tracers.material[t] = kLostTracer;
        return 1;
      }
      cells_moved = std::max(cells_moved, std::abs(u[a]) * dt / dx[a]);
      x[a] = apply_faces(moved, lo[a], hi[a], faces[2 * a], faces[2 * a + 1]);
      if (std::isnan(x[a])) {
        tracers.material[t] = kRemovedTracer;
        return 1;
      }
    }
    for (int a = 0; a < 3; ++a) tracers.position[a][t] = x[a];
    return 0;
  };
  const auto count = static_cast<std::ptrdiff_t>(tracers.size());
  std::size_t leaving = 0;
  double farthest = 0.0;  // the empty-cell fill's reach (empty_cell_fill.hpp)
#pragma omp parallel for schedule(static) reduction(+ : leaving) reduction(max : farthest) \
    if (count >= kMinParallelCount)
  for (std::ptrdiff_t t = 0; t < count; ++t) leaving += move(static_cast<std::size_t>(t), farthest);
  const std::size_t lost = leaving > 0 ? tracers.compact() : 0;
  if (lost > 0)
    throw Error("tracer advection: " + std::to_string(lost) +
                " tracers reached a non-finite position; the velocity field holds NaN or inf");
  return {.removed = leaving - lost, .max_cells_moved = farthest};
}

}  // namespace mpfd::fdm
