#include "common/config/shapes.hpp"

#include <algorithm>
#include <cmath>

#include "common/core/error.hpp"

namespace mpfd::config {
namespace {

double dot(const Vec3& a, const Vec3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vec3 unit(const Vec3& v) {
  const double n = std::sqrt(dot(v, v));
  return {v[0] / n, v[1] / n, v[2] / n};
}

bool inside(const Box& b, const Vec3& p) {
  for (int i = 0; i < 3; ++i) {
    if (p[i] < b.lower[i] || p[i] > b.upper[i]) return false;
  }
  return true;
}

bool inside(const Sphere& s, const Vec3& p) {
  const Vec3 d{p[0] - s.center[0], p[1] - s.center[1], p[2] - s.center[2]};
  return dot(d, d) <= s.radius * s.radius;
}

bool inside(const Cylinder& c, const Vec3& p) {
  const Vec3 a = unit(c.axis);
  const Vec3 d{p[0] - c.base[0], p[1] - c.base[1], p[2] - c.base[2]};
  const double along = dot(d, a);
  if (along < 0.0 || along > c.length) return false;
  const Vec3 radial{d[0] - along * a[0], d[1] - along * a[1], d[2] - along * a[2]};
  return dot(radial, radial) <= c.radius * c.radius;
}

bool inside(const Union& u, const Vec3& p) {
  return std::any_of(u.parts.begin(), u.parts.end(),
                     [&](const Shape& s) { return contains(s, p); });
}

bool inside(const Difference& d, const Vec3& p) {
  if (d.parts.empty() || !contains(d.parts.front(), p)) return false;
  return std::none_of(d.parts.begin() + 1, d.parts.end(),
                      [&](const Shape& s) { return contains(s, p); });
}

Box box_of(const Box& b) {
  return b;
}

Box box_of(const Sphere& s) {
  Box b;
  for (int i = 0; i < 3; ++i) {
    b.lower[i] = s.center[i] - s.radius;
    b.upper[i] = s.center[i] + s.radius;
  }
  return b;
}

// The two end discs bound the cylinder; a disc of radius r with unit normal a
// extends r sqrt(1 - a_i^2) about its centre along axis i.
Box box_of(const Cylinder& c) {
  const Vec3 a = unit(c.axis);
  Box b;
  for (int i = 0; i < 3; ++i) {
    const double top = c.base[i] + c.length * a[i];
    const double half = c.radius * std::sqrt(std::max(0.0, 1.0 - a[i] * a[i]));
    b.lower[i] = std::min(c.base[i], top) - half;
    b.upper[i] = std::max(c.base[i], top) + half;
  }
  return b;
}

Box box_of(const Union& u) {
  MPFD_ASSERT(!u.parts.empty(), "a union has at least one part");
  Box b = bounding_box(u.parts.front());
  for (const Shape& s : u.parts) {
    const Box p = bounding_box(s);
    for (int i = 0; i < 3; ++i) {
      b.lower[i] = std::min(b.lower[i], p.lower[i]);
      b.upper[i] = std::max(b.upper[i], p.upper[i]);
    }
  }
  return b;
}

Box box_of(const Difference& d) {
  MPFD_ASSERT(!d.parts.empty(), "a difference has at least one part");
  return bounding_box(d.parts.front());
}

}  // namespace

bool contains(const Shape& shape, const Vec3& point) {
  return std::visit([&](const auto& s) { return inside(s, point); }, shape.kind);
}

Box bounding_box(const Shape& shape) {
  return std::visit([](const auto& s) { return box_of(s); }, shape.kind);
}

}  // namespace mpfd::config
