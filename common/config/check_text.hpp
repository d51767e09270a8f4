#pragma once
// Internal: how the scene checks print numbers, points and key paths in their
// messages, and the grid facts they share.

#include <cstdio>
#include <string>

#include "common/config/scene.hpp"

namespace mpfd::config {

// Computed values such as grid lines carry round-off; 12 digits hide it.
inline std::string num(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.12g", x);
  return buffer;
}

inline std::string text(const Vec3& v) {
  std::string out = "[";
  for (int i = 0; i < 3; ++i) {
    if (i > 0) out += ", ";
    out += num(v[i]);
  }
  return out + "]";
}

inline std::string item(const std::string& list, std::size_t i) {
  return list + "[" + std::to_string(i) + "]";
}

inline std::string domain_text(const Domain& d) {
  return "the domain " + text(d.lower) + " to " + text(d.upper);
}

inline double cell_size(const Domain& d, int axis) {
  return (d.upper[axis] - d.lower[axis]) / d.cells[axis];
}

// Coordinates closer than this fraction of a cell are equal.
inline constexpr double kGridTolerance = 1e-6;

inline bool active(const Domain& d, int axis) {
  return d.cells[axis] > 1;
}

// The open boxes share volume on every active axis.
inline bool overlap(const Domain& dom, const Box& a, const Vec3& lower, const Vec3& upper) {
  for (int i = 0; i < 3; ++i) {
    if (!active(dom, i)) continue;
    const double tol = kGridTolerance * cell_size(dom, i);
    if (a.upper[i] <= lower[i] + tol || a.lower[i] >= upper[i] - tol) return false;
  }
  return true;
}

inline bool within(const Domain& dom, const Box& a, const Vec3& lower, const Vec3& upper) {
  for (int i = 0; i < 3; ++i) {
    if (!active(dom, i)) continue;
    const double tol = kGridTolerance * cell_size(dom, i);
    if (a.lower[i] < lower[i] - tol || a.upper[i] > upper[i] + tol) return false;
  }
  return true;
}

}  // namespace mpfd::config
