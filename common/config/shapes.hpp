#pragma once
// Solid shapes of bodies and charges: three primitives and their union and
// difference, with the point-inside test the particle and cell fillers use.
// All shapes are closed sets: a point on the surface is inside.

#include <array>
#include <variant>
#include <vector>

namespace mpfd::config {

using Vec3 = std::array<double, 3>;

struct Shape;

struct Box {
  Vec3 lower{};  ///< [m]
  Vec3 upper{};  ///< [m], > lower on every axis
};

struct Sphere {
  Vec3 center{};        ///< [m]
  double radius = 0.0;  ///< [m], > 0
};

struct Cylinder {
  Vec3 base{};          ///< centre of the bottom face [m]
  Vec3 axis{};          ///< direction from the bottom to the top face, any nonzero length [-]
  double radius = 0.0;  ///< [m], > 0
  double length = 0.0;  ///< [m], > 0
};

struct Union {
  std::vector<Shape> parts;  ///< inside any part
};

struct Difference {
  std::vector<Shape> parts;  ///< inside parts[0] and outside every later part
};

struct Shape {
  std::variant<Box, Sphere, Cylinder, Union, Difference> kind;
};

/// True if `point` [m] lies inside or on the surface of `shape`.
bool contains(const Shape& shape, const Vec3& point);

/// Smallest axis-aligned box holding `shape` (for a difference: its first part).
Box bounding_box(const Shape& shape);

}  // namespace mpfd::config
