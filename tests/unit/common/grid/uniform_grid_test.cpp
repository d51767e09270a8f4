#include "common/grid/uniform_grid.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/core/error.hpp"

namespace mpfd::grid {
namespace {

using ::testing::HasSubstr;

TEST(UniformGrid, CellIndexRoundTripsAndIsXFastest) {
  const UniformGrid g({0, 0, 0}, {1, 1, 1}, {4, 3, 2});
  EXPECT_EQ(g.cell_count(), 24u);
  EXPECT_EQ(g.cell_index(1, 0, 0), 1u);
  EXPECT_EQ(g.cell_index(0, 1, 0), 4u);
  EXPECT_EQ(g.cell_index(0, 0, 1), 12u);
  for (std::size_t n = 0; n < g.cell_count(); ++n) EXPECT_EQ(g.cell_index(g.cell_of_index(n)), n);
}

TEST(UniformGrid, NodeIndexRoundTripsWithOneLayerOnInactiveAxes) {
  const UniformGrid g({0, 0, 0}, {0.1, 0.2, 0.3}, {5, 3, 1});
  EXPECT_EQ(g.dimension(), 2);
  EXPECT_EQ(g.nodes(), (Index3{6, 4, 1}));
  EXPECT_EQ(g.node_count(), 24u);
  for (std::size_t n = 0; n < g.node_count(); ++n) EXPECT_EQ(g.node_index(g.node_of_index(n)), n);
  // The single z node layer sits mid-thickness.
  EXPECT_DOUBLE_EQ(g.node_position({0, 0, 0})[2], 0.15);
}

TEST(UniformGrid, FromBoundsGivesSpacingAndVolumeOfA1DSlab) {
  const auto g = UniformGrid::from_bounds({0, 0, 0}, {0.1, 0.01, 0.01}, {1000, 1, 1});
  EXPECT_EQ(g.dimension(), 1);
  EXPECT_DOUBLE_EQ(g.spacing()[0], 1e-4);
  EXPECT_DOUBLE_EQ(g.cell_volume(), 1e-4 * 0.01 * 0.01);
  EXPECT_NEAR(g.upper()[0], 0.1, 1e-15);
}

TEST(UniformGrid, CellCentresAreMidwayBetweenNodes) {
  const UniformGrid g({-1, 2, 0}, {0.5, 0.25, 1}, {4, 4, 4});
  const Vec3 c = g.cell_center({1, 2, 3});
  const Vec3 lo = g.node_position({1, 2, 3});
  const Vec3 hi = g.node_position({2, 3, 4});
  for (int a = 0; a < 3; ++a) EXPECT_DOUBLE_EQ(c[a], 0.5 * (lo[a] + hi[a]));
}

TEST(UniformGrid, LocateFindsCellAndLocalCoordinates) {
  const UniformGrid g({0, 0, 0}, {0.1, 0.1, 0.1}, {10, 10, 10});
  const auto where = g.locate({0.25, 0.05, 0.999});
  ASSERT_TRUE(where.has_value());
  EXPECT_EQ(where->cell, (Index3{2, 0, 9}));
  EXPECT_NEAR(where->local[0], 0.5, 1e-12);
  EXPECT_NEAR(where->local[1], 0.5, 1e-12);
  EXPECT_NEAR(where->local[2], 0.99, 1e-12);
}

TEST(UniformGrid, LocateIsHalfOpenAtTheDomainBounds) {
  const UniformGrid g({0, 0, 0}, {0.1, 1, 1}, {10, 1, 1});
  EXPECT_TRUE(g.locate({0.0, 0.5, 0.5}).has_value());
  EXPECT_FALSE(g.locate({1.0, 0.5, 0.5}).has_value());
  EXPECT_FALSE(g.locate({-1e-12, 0.5, 0.5}).has_value());
  const auto last = g.locate({std::nextafter(1.0, 0.0), 0.5, 0.5});
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->cell[0], 9);
  EXPECT_LT(last->local[0], 1.0);
}

TEST(UniformGrid, RejectsNonPositiveSpacingNamingTheAxis) {
  try {
    const UniformGrid g({0, 0, 0}, {0.1, 0.0, 0.1}, {1, 1, 1});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("spacing along y"));
  }
  EXPECT_THROW(UniformGrid::from_bounds({0, 0, 0}, {1, 1, 1}, {0, 1, 1}), Error);
  EXPECT_THROW(UniformGrid::from_bounds({0, 0, 0}, {1, -1, 1}, {1, 1, 1}), Error);
}

}  // namespace
}  // namespace mpfd::grid
