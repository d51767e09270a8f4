#pragma once
// Internal: the MPFD scene schema, built from the machinery of
// schema_table.hpp. scene_schema.cpp holds the top-level tables,
// material_schema.cpp the material models, shape_schema.cpp the shapes.
// A new material model is one table and one add() line in material_schema.cpp.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/config/scene.hpp"
#include "common/config/schema_table.hpp"

namespace mpfd::config::schema {

/// The whole scene file.
const Table<Scene>& scene_table();

/// One entry of `materials`.
std::shared_ptr<const Table<Material>> material_table();

/// Reports at `c`'s `upper` key each axis where upper <= lower.
void check_box(const Vec3& lower, const Vec3& upper, const Cursor& c);

/// A shape: a map with exactly one key naming its kind; union and difference nest.
class ShapeType {
 public:
  using Value = Shape;
  std::optional<Shape> read(const Cursor& c) const;
  std::string describe() const;
  std::string unit() const { return ""; }
  void children(std::vector<const TableDoc*>& out) const;
};

}  // namespace mpfd::config::schema
