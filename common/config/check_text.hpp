#pragma once
// Internal: how the scene checks print numbers, points and key paths in their
// messages, and the grid facts they share.

#include <cstdio>
#include <string>

#include "common/config/scene.hpp"

namespace mpfd::config {

inline constexpr const char* kAxisNames[] = {"x", "y", "z"};
inline constexpr const char* kFaceNames[] = {"x_lower", "x_upper", "y_lower",
                                             "y_upper", "z_lower", "z_upper"};

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

}  // namespace mpfd::config
