// Point-inside tests and bounding boxes of the scene shapes: bodies and
// charges are filled by contains(), so a wrong answer puts material in the
// wrong cells.
#include "common/config/shapes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace mpfd::config {
namespace {

// Tolerance for bounding boxes computed with square roots: a few ulps of 1.
constexpr double kTol = 1e-12;

const Shape kUnitBox{Box{{0, 0, 0}, {1, 1, 1}}};
const Shape kBall{Sphere{{0, 0, 0}, 0.5}};

TEST(Shapes, Box_is_closed_and_axis_aligned) {
  EXPECT_TRUE(contains(kUnitBox, {0.5, 0.5, 0.5}));
  EXPECT_TRUE(contains(kUnitBox, {0.0, 1.0, 0.5}));  // on the surface
  EXPECT_FALSE(contains(kUnitBox, {1.0 + 1e-12, 0.5, 0.5}));
  EXPECT_FALSE(contains(kUnitBox, {0.5, -1e-12, 0.5}));
  EXPECT_FALSE(contains(kUnitBox, {0.5, 0.5, 2.0}));
}

TEST(Shapes, Sphere_holds_points_within_its_radius) {
  EXPECT_TRUE(contains(kBall, {0.0, 0.0, 0.0}));
  EXPECT_TRUE(contains(kBall, {0.5, 0.0, 0.0}));
  EXPECT_TRUE(contains(kBall, {0.28, 0.28, 0.28}));  // |p| = 0.485
  EXPECT_FALSE(contains(kBall, {0.3, 0.3, 0.3}));    // |p| = 0.520, inside the bounding box
}

TEST(Shapes, Cylinder_along_an_oblique_axis_measures_along_and_across_it) {
  // Axis (1, 1, 0) of any length, from the origin, length sqrt(2), radius 0.1.
  const Shape c{Cylinder{{0, 0, 0}, {2, 2, 0}, 0.1, std::sqrt(2.0)}};
  EXPECT_TRUE(contains(c, {0.5, 0.5, 0.0}));
  EXPECT_TRUE(contains(c, {0.999, 0.999, 0.0}));  // just below the top face
  EXPECT_TRUE(contains(c, {0.5, 0.5, 0.099}));    // just inside the mantle
  EXPECT_FALSE(contains(c, {0.5, 0.5, 0.101}));
  EXPECT_FALSE(contains(c, {1.1, 1.1, 0.0}));      // beyond the top face
  EXPECT_FALSE(contains(c, {-0.05, -0.05, 0.0}));  // below the bottom face
  EXPECT_TRUE(contains(c, {0.55, 0.45, 0.0}));     // 0.0707 off the axis
  EXPECT_FALSE(contains(c, {0.6, 0.4, 0.0}));      // 0.141 off the axis
}

TEST(Shapes, Union_holds_what_any_part_holds) {
  const Shape u{Union{{kUnitBox, Shape{Sphere{{2, 0, 0}, 0.5}}}}};
  EXPECT_TRUE(contains(u, {0.5, 0.5, 0.5}));
  EXPECT_TRUE(contains(u, {2.4, 0.0, 0.0}));
  EXPECT_FALSE(contains(u, {1.3, 0.0, 0.0}));
}

TEST(Shapes, Difference_removes_later_parts_from_the_first) {
  const Shape hollow{Difference{{kUnitBox, Shape{Sphere{{0.5, 0.5, 0.5}, 0.3}}}}};
  EXPECT_FALSE(contains(hollow, {0.5, 0.5, 0.5}));
  EXPECT_TRUE(contains(hollow, {0.05, 0.05, 0.05}));
  EXPECT_FALSE(contains(hollow, {1.5, 0.5, 0.5}));
}

TEST(Shapes, Nested_union_inside_difference) {
  const Shape two_holes{Difference{
      {kUnitBox, Shape{Union{{Shape{Sphere{{0, 0, 0}, 0.2}}, Shape{Sphere{{1, 1, 1}, 0.2}}}}}}}};
  EXPECT_FALSE(contains(two_holes, {0.05, 0.05, 0.05}));
  EXPECT_FALSE(contains(two_holes, {0.95, 0.95, 0.95}));
  EXPECT_TRUE(contains(two_holes, {0.5, 0.5, 0.5}));
}

TEST(Shapes, Bounding_boxes_enclose_each_primitive_tightly) {
  const Box ball = bounding_box(kBall);
  EXPECT_EQ(ball.lower, (Vec3{-0.5, -0.5, -0.5}));
  EXPECT_EQ(ball.upper, (Vec3{0.5, 0.5, 0.5}));

  // A cylinder along z: its discs extend by the radius in x and y only.
  const Box z = bounding_box(Shape{Cylinder{{1, 2, 3}, {0, 0, 5}, 0.5, 2.0}});
  EXPECT_NEAR(z.lower[0], 0.5, kTol);
  EXPECT_NEAR(z.upper[1], 2.5, kTol);
  EXPECT_NEAR(z.lower[2], 3.0, kTol);
  EXPECT_NEAR(z.upper[2], 5.0, kTol);

  const Box u = bounding_box(Shape{Union{{kUnitBox, Shape{Sphere{{2, 0, 0}, 0.5}}}}});
  EXPECT_EQ(u.lower, (Vec3{0, -0.5, -0.5}));
  EXPECT_EQ(u.upper, (Vec3{2.5, 1, 1}));

  const Box d = bounding_box(Shape{Difference{{kUnitBox, kBall}}});
  EXPECT_EQ(d.lower, (Vec3{0, 0, 0}));
  EXPECT_EQ(d.upper, (Vec3{1, 1, 1}));
}

}  // namespace
}  // namespace mpfd::config
