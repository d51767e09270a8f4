#include <cmath>
#include <string>
#include <variant>

#include "common/config/check_text.hpp"
#include "common/config/scene_checks.hpp"

namespace mpfd::config {
namespace {

// Radii closer than this many cell sizes to a grid line are on it (the
// spherical MPM seeds whole cells per layer).
constexpr double kRadiusTolerance = 1e-9;

void check_line(const Scene& s, Diagnostics& d) {
  const Domain& dom = s.domain;
  if (dom.lower != Vec3{0.0, 0.0, 0.0})
    d.error("domain.lower",
            "expected [0, 0, 0] with geometry spherical (x is the radius), got " + text(dom.lower));
  if (dom.cells[1] != 1 || dom.cells[2] != 1)
    d.error("domain.cells", "expected [n, 1, 1] with geometry spherical (one radial line), got [" +
                                std::to_string(dom.cells[0]) + ", " + std::to_string(dom.cells[1]) +
                                ", " + std::to_string(dom.cells[2]) + "]");
  if (d.clean("solver") && s.solver.method != Method::mpm)
    d.error("domain.geometry", "spherical is run by mpm_solver run; expected solver.method mpm");
  if (d.clean("solver") && s.solver.mpm.shape_function == ShapeFunction::cpgimp)
    d.error("solver.mpm.shape_function",
            "expected linear or gimp with geometry spherical (the radial grid has no cpgimp)");
  if (d.clean("solver") && s.solver.mpm.update == MpmUpdate::usavg)
    d.error("solver.mpm.update",
            "expected musl with geometry spherical (the 1D spherical MPM has no usavg yet)");
  if (!d.clean("boundaries")) return;
  if (s.boundaries[Face::x_lower] != BoundaryKind::symmetry)
    d.error("boundaries.x_lower",
            "expected symmetry with geometry spherical (x = 0 is the centre of the sphere)");
  const BoundaryKind outer = s.boundaries[Face::x_upper];
  if (outer != BoundaryKind::outflow && outer != BoundaryKind::non_reflecting)
    d.error("boundaries.x_upper",
            "expected outflow (a free surface) or non_reflecting (transmitting) with geometry "
            "spherical");
}

// Each region must be a sphere about the origin with its radius on a grid line,
// all with the same particle count: they become the layers of one radial line.
void check_spherical_regions(const Scene& s, Diagnostics& d) {
  const double h = cell_size(s.domain, 0);
  int particles = 0;
  std::string first;
  const auto check = [&](const Shape& shape, int per_axis, const std::string& path) {
    const auto* ball = std::get_if<Sphere>(&shape.kind);
    if (!ball || ball->center != Vec3{0.0, 0.0, 0.0}) {
      d.error(path + ".shape",
              "expected a sphere centred at [0, 0, 0] with geometry spherical (one shell of "
              "the radial line)");
      return;
    }
    const double cells = ball->radius / h;
    if (std::abs(cells - std::round(cells)) > kRadiusTolerance * std::max(1.0, cells))
      d.error(path + ".shape", "expected a radius on a grid line (a multiple of the cell size " +
                                   num(h) + " m), got " + num(ball->radius) + " m");
    if (per_axis < 2)
      d.error(path + ".particles_per_axis",
              "expected >= 2 with geometry spherical (the Gauss points of each shell), got " +
                  std::to_string(per_axis));
    if (first.empty()) {
      particles = per_axis;
      first = path;
    } else if (per_axis != particles) {
      d.error(path + ".particles_per_axis",
              "expected " + std::to_string(particles) + " as " + first +
                  " (one particle count per cell for the radial line), got " +
                  std::to_string(per_axis));
    }
  };
  for (std::size_t i = 0; i < s.bodies.size(); ++i)
    check(s.bodies[i].shape, s.bodies[i].particles_per_axis, item("bodies", i));
  for (std::size_t i = 0; i < s.charges.size(); ++i) {
    const Charge& c = s.charges[i];
    check(c.shape, c.particles_per_axis, item("charges", i));
    if (c.burn == Burn::instantaneous)
      d.error(item("charges", i) + ".burn",
              "expected program with geometry spherical (the radial line burns from the centre)");
    else if (c.detonation_point && *c.detonation_point != Vec3{0.0, 0.0, 0.0})
      d.error(item("charges", i) + ".detonation_point",
              "expected [0, 0, 0] with geometry spherical (the centre), got " +
                  text(*c.detonation_point));
  }
}

}  // namespace

void check_spherical_geometry(const Scene& s, Diagnostics& d) {
  if (s.domain.geometry != Geometry::spherical) return;
  check_line(s, d);
  if (d.clean("bodies") && d.clean("charges")) check_spherical_regions(s, d);
}

}  // namespace mpfd::config
