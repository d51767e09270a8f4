#include <cmath>
#include <memory>

#include "common/config/scene_schema.hpp"

namespace mpfd::config::schema {
namespace {

const Fixed<Number, 3> kShapePoint{Number("m")};
const Number kLength{"m", Range::above(0)};

std::string parts_rule(std::size_t min_parts) {
  return "a list of " + std::to_string(min_parts) + " or more shapes";
}

struct ShapeTables {
  std::shared_ptr<Table<Box>> box;
  std::shared_ptr<Table<Sphere>> sphere;
  std::shared_ptr<Table<Cylinder>> cylinder;
  TableDoc doc;
};

const std::vector<std::string> kKinds{"box", "sphere", "cylinder", "union", "difference"};

const ShapeTables& tables() {
  static const ShapeTables built = [] {
    ShapeTables t;
    t.box = std::make_shared<Table<Box>>("shape: box", "Axis-aligned box.");
    t.box->required("lower", &Box::lower, kShapePoint, "lowest corner")
        .required("upper", &Box::upper, kShapePoint, "highest corner")
        .rule("upper > lower on every axis",
              [](const Box& b, const Cursor& c) { check_box(b.lower, b.upper, c); });
    t.sphere = std::make_shared<Table<Sphere>>("shape: sphere", "Ball.");
    t.sphere->required("center", &Sphere::center, kShapePoint, "centre")
        .required("radius", &Sphere::radius, kLength, "radius");
    t.cylinder = std::make_shared<Table<Cylinder>>("shape: cylinder", "Solid circular cylinder.");
    t.cylinder->required("base", &Cylinder::base, kShapePoint, "centre of the bottom face")
        .required("axis", &Cylinder::axis, Fixed<Number, 3>(Number("-")),
                  "direction from the bottom to the top face; any nonzero length")
        .required("radius", &Cylinder::radius, kLength, "radius")
        .required("length", &Cylinder::length, kLength, "distance between the faces")
        .rule("axis is not [0, 0, 0]", [](const Cylinder& cyl, const Cursor& c) {
          const Vec3& a = cyl.axis;
          if (a[0] == 0.0 && a[1] == 0.0 && a[2] == 0.0) {
            c.error_at("axis", "expected a nonzero direction, got [0, 0, 0]");
          }
        });
    t.doc = TableDoc{
        "shape",
        "A solid: a map with exactly one of these keys. Shapes are closed (a point "
        "on the surface is inside); union and difference nest any shapes.",
        {KeyDoc{"box", "a map, see `shape: box`", "", "one of", "axis-aligned box"},
         KeyDoc{"sphere", "a map, see `shape: sphere`", "", "one of", "ball"},
         KeyDoc{"cylinder", "a map, see `shape: cylinder`", "", "one of", "circular cylinder"},
         KeyDoc{"union", parts_rule(1), "", "one of", "inside any of the shapes"},
         KeyDoc{"difference", parts_rule(2), "", "one of",
                "inside the first shape and outside all the others"}},
        {},
        {&t.box->doc(), &t.sphere->doc(), &t.cylinder->doc()}};
    return t;
  }();
  return built;
}

template <class T>
std::optional<Shape> read_primitive(const Table<T>& table, const Cursor& c) {
  T out{};
  if (!table.read(c, out)) return std::nullopt;
  return Shape{out};
}

}  // namespace

void check_box(const Vec3& lower, const Vec3& upper, const Cursor& c) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (upper[i] <= lower[i]) {
      c.error_at("upper", std::string("expected upper > lower along ") + kAxes[i] + ", got " +
                              format_number(upper[i]) + " <= " + format_number(lower[i]));
    }
  }
}

std::string ShapeType::describe() const {
  return "a map with exactly one key: " + join(kKinds, ", ");
}

void ShapeType::children(std::vector<const TableDoc*>& out) const {
  out.push_back(&tables().doc);
}

std::optional<Shape> ShapeType::read(const Cursor& c) const {
  if (!check_keys(c, kKinds)) return std::nullopt;
  if (c.node.size() != 1) {
    c.expected(describe());
    return std::nullopt;
  }
  const std::string kind = c.node.begin()->first.Scalar();
  const auto value = find_key(c, kind);
  if (!value) return std::nullopt;
  const ShapeTables& t = tables();
  if (kind == "box") return read_primitive(*t.box, *value);
  if (kind == "sphere") return read_primitive(*t.sphere, *value);
  if (kind == "cylinder") return read_primitive(*t.cylinder, *value);
  if (kind != "union" && kind != "difference") return std::nullopt;
  const std::size_t min_parts = kind == "union" ? 1 : 2;
  if (!value->node.IsSequence() || value->node.size() < min_parts) {
    value->expected(parts_rule(min_parts));
    return std::nullopt;
  }
  std::vector<Shape> parts;
  for (std::size_t i = 0; i < value->node.size(); ++i) {
    auto part = read(value->child("[" + std::to_string(i) + "]", value->node[i], value->mark));
    if (part) parts.push_back(std::move(*part));
  }
  if (parts.size() != value->node.size()) return std::nullopt;
  if (kind == "union") return Shape{Union{std::move(parts)}};
  return Shape{Difference{std::move(parts)}};
}

}  // namespace mpfd::config::schema
