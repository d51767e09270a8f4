#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "common/config/check_text.hpp"
#include "common/config/scene_checks.hpp"

namespace mpfd::config {
namespace {

// The ball the 1D start fills is this many handoff radii (the remap reaches
// past the front; design §4).
constexpr double kBallFactor = 1.25;

double distance_to_box(const Vec3& p, const Vec3& lower, const Vec3& upper) {
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double gap = std::max({lower[i] - p[i], 0.0, p[i] - upper[i]});
    sum += gap * gap;
  }
  return std::sqrt(sum);
}

// The FSI zone is a slab across the domain: every face but one lies on the
// domain's boundary (T §3.4.4; coupler/run/afdmp_layout).
void check_fsi_zone(const Scene& s, const MpmZone& zone, Diagnostics& d) {
  if (!zone.activation_pressure)
    d.error("zones.mpm",
            "activation_pressure is required with solver.method afdmp (phase 3 starts when the "
            "FDM pressure next to the FSI zone passes it, T §3.2.3)");
  std::vector<std::string> inner;
  for (int i = 0; i < 3; ++i) {
    if (!active(s.domain, i)) continue;
    const double tol = kGridTolerance * cell_size(s.domain, i);
    if (zone.lower[i] > s.domain.lower[i] + tol)
      inner.push_back(std::string(kAxisNames[i]) + " = " + num(zone.lower[i]));
    if (zone.upper[i] < s.domain.upper[i] - tol)
      inner.push_back(std::string(kAxisNames[i]) + " = " + num(zone.upper[i]));
  }
  if (inner.size() != 1)
    d.error("zones.mpm",
            "expected an FSI zone with exactly one face inside the domain (a slab across it, "
            "the other faces on the domain's boundary), got " +
                std::to_string(inner.size()) + (inner.empty() ? "" : ": " + join(inner)));
}

void check_afdmp_regions(const Scene& s, Diagnostics& d) {
  const std::optional<MpmZone>& zone = s.zones ? s.zones->mpm : std::nullopt;
  for (std::size_t i = 0; i < s.charges.size(); ++i) {
    if (zone && overlap(s.domain, bounding_box(s.charges[i].shape), zone->lower, zone->upper))
      d.error(item("charges", i) + ".shape", "expected a charge outside zones.mpm " +
                                                 text(zone->lower) + " to " + text(zone->upper) +
                                                 " (it detonates in the fluid zone, T §3.2.1)");
  }
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Material* m = find_material(s, s.bodies[i].state.material);
    if (!m || !has_strength(*m)) continue;
    if (!zone) {
      d.error(item("bodies", i),
              "a body with a strength model needs zones.mpm around it with solver.method afdmp "
              "(structures live in the FSI zone, T §3.2.3)");
    } else if (!within(s.domain, bounding_box(s.bodies[i].shape), zone->lower, zone->upper)) {
      d.error(item("bodies", i) + ".shape",
              "expected a body with a strength model inside zones.mpm " + text(zone->lower) +
                  " to " + text(zone->upper) + " (structures live in the FSI zone, T §3.2.3)");
    }
  }
}

bool same_state(const MaterialState& a, const MaterialState& b) {
  return a.material == b.material && a.density == b.density && a.velocity == b.velocity &&
         a.pressure == b.pressure && a.specific_internal_energy == b.specific_internal_energy;
}

// start: spherical: one centre-initiated sphere in a 3D grid, and a ball around
// it that the 1D stage owns: background only, away from the FSI zone and from
// every face but symmetry planes through its centre.
void check_spherical_start(const Scene& s, Diagnostics& d) {
  const std::string start = "solver.afdmp.start";
  const AfdmpSpherical& o = s.solver.afdmp.spherical;
  if (!active(s.domain, 0) || !active(s.domain, 1) || !active(s.domain, 2))
    d.error(start, "spherical needs a 3D grid (domain.cells > 1 on every axis), got [" +
                       std::to_string(s.domain.cells[0]) + ", " +
                       std::to_string(s.domain.cells[1]) + ", " +
                       std::to_string(s.domain.cells[2]) + "]");
  if (!o.handoff_radius)
    d.error("solver.afdmp.spherical",
            "handoff_radius is required with start: spherical (the 1D stage ends when the "
            "front reaches it)");
  if (s.charges.size() != 1) {
    d.error(start, "spherical expects exactly one charge, got " + std::to_string(s.charges.size()));
    return;
  }
  const Charge& c = s.charges[0];
  const auto* ball = std::get_if<Sphere>(&c.shape.kind);
  if (!ball) {
    d.error("charges[0].shape", "expected a sphere with solver.afdmp.start: spherical");
    return;
  }
  if (c.burn == Burn::instantaneous) {
    d.error("charges[0].burn",
            "expected program with solver.afdmp.start: spherical (the 1D stage burns from the "
            "centre)");
  } else if (c.detonation_point && *c.detonation_point != ball->center) {
    d.error("charges[0].detonation_point", "expected the sphere's centre " + text(ball->center) +
                                               " with solver.afdmp.start: spherical, got " +
                                               text(*c.detonation_point));
  }
  double smallest = cell_size(s.domain, 0);
  for (int i = 1; i < 3; ++i) smallest = std::min(smallest, cell_size(s.domain, i));
  const double h = o.grid_spacing.value_or(smallest / 4.0);
  const double cells = ball->radius / h;
  if (std::abs(cells - std::round(cells)) > 1e-9 * std::max(1.0, cells))
    d.error("solver.afdmp.spherical",
            "expected the charge radius " + num(ball->radius) +
                " m to be a multiple of the 1D grid spacing, got spacing " + num(h) +
                " m; set grid_spacing to e.g. " +
                num(ball->radius / std::max(1.0, std::ceil(cells))) + " m");
  if (!o.handoff_radius) return;
  const std::string handoff = "solver.afdmp.spherical.handoff_radius";
  if (*o.handoff_radius <= ball->radius) {
    d.error(handoff, "expected more than the charge radius " + num(ball->radius) + " m, got " +
                         num(*o.handoff_radius));
    return;
  }
  const double reach = kBallFactor * *o.handoff_radius;
  const std::string what = "the ball of 1.25 x handoff_radius = " + num(reach) +
                           " m around the charge centre " + text(ball->center);
  if (s.zones && s.zones->mpm) {
    const double gap = distance_to_box(ball->center, s.zones->mpm->lower, s.zones->mpm->upper);
    if (gap < reach)
      d.error(handoff, what + " meets zones.mpm at " + num(gap) +
                           " m; expected handoff_radius <= " + num(gap / kBallFactor) + " m");
  }
  for (int f = 0; f < 6; ++f) {
    const int axis = f / 2;
    const double plane = f % 2 == 0 ? s.domain.lower[axis] : s.domain.upper[axis];
    const double gap = std::abs(ball->center[axis] - plane);
    const BoundaryKind kind = s.boundaries.faces[static_cast<std::size_t>(f)];
    const bool mirror_through_centre =
        kind == BoundaryKind::symmetry && gap <= kGridTolerance * cell_size(s.domain, axis);
    if (gap < reach && !mirror_through_centre)
      d.error(handoff, what + " meets the " + kFaceNames[f] + " face at " + num(gap) +
                           " m (only symmetry planes through the centre may); expected "
                           "handoff_radius <= " +
                           num(gap / kBallFactor) + " m");
  }
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const Box box = bounding_box(s.bodies[i].shape);
    if (distance_to_box(ball->center, box.lower, box.upper) < reach &&
        !same_state(s.bodies[i].state, s.initial))
      d.error(item("bodies", i),
              "meets " + what +
                  "; expected the material and state of `initial` there (the 1D stage fills "
                  "the ball with the background)");
  }
}

}  // namespace

void check_afdmp(const Scene& s, Diagnostics& d) {
  if (!d.clean("solver") || !d.clean("charges") || !d.clean("bodies") || !d.clean("zones") ||
      !d.clean("materials"))
    return;
  if (s.solver.method != Method::afdmp) {
    if (s.solver.afdmp.start == AfdmpStart::spherical)
      d.error("solver.afdmp.start",
              "spherical is used only by solver.method afdmp; remove it or choose afdmp");
    return;
  }
  if (s.charges.empty())
    d.error("solver.method",
            "afdmp needs at least one charge (phase 1 is its detonation, T §3.2.1); got none");
  if (s.zones && s.zones->mpm) {
    check_fsi_zone(s, *s.zones->mpm, d);
    if (s.solver.mpm.contact)
      d.error("solver.mpm.contact",
              "not with an FSI zone under afdmp: the MPM refuses coupler particles with "
              "contact (MpmSolver::refuse_unsupported_coupling)");
  }
  check_afdmp_regions(s, d);
  if (s.solver.afdmp.start == AfdmpStart::spherical) check_spherical_start(s, d);
}

}  // namespace mpfd::config
