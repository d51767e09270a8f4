// The fluid box as its own grid and the copies/transposes between box, whole
// grid and wire order (coupler/handoff/sub_grid.hpp): checked by round trips
// and against the index formulas of UniformGrid and proto/README.md §11.
#include "coupler/handoff/sub_grid.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "common/core/error.hpp"

namespace mpfd::coupler::handoff {
namespace {

using ::testing::HasSubstr;

const grid::UniformGrid kWhole({-0.2, 0.1, 0.3}, {0.1, 0.2, 0.15}, {7, 4, 5});

TEST(SubGrid, HasTheBoxCellsAtTheirPlaceWithTheSameSpacing) {
  const CellBox box{{2, 0, 1}, {7, 4, 3}};
  const grid::UniformGrid sub = sub_grid(kWhole, box);
  EXPECT_EQ(sub.cells(), (grid::Index3{5, 4, 2}));
  EXPECT_EQ(sub.spacing(), kWhole.spacing());
  EXPECT_EQ(sub.dimension(), 3);
  for (std::size_t c = 0; c < sub.cell_count(); ++c) {
    const grid::Index3 local = sub.cell_of_index(c);
    const grid::Vec3 x = sub.cell_center(local);
    const grid::Vec3 y = kWhole.cell_center({local[0] + 2, local[1], local[2] + 1});
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(x[a], y[a], 1e-15) << "cell " << c << " axis " << a;
  }
}

TEST(SubGrid, RefusesABoxOneCellWideOnAnActiveAxisOrOutsideTheGrid) {
  const auto message = [](const CellBox& box) {
    try {
      (void)sub_grid(kWhole, box);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(message({{6, 0, 0}, {7, 4, 5}}), HasSubstr(">= 2 cells wide along x"));
  EXPECT_THAT(message({{0, 0, 0}, {8, 4, 5}}), HasSubstr("[0, 8) x [0, 4) x [0, 5)"));
}

TEST(SubGrid, EmbedThenExtractReturnsTheBoxAndTouchesNothingElse) {
  const CellBox box{{3, 1, 0}, {6, 4, 5}};
  const int width = 2;  // a per-material array of two materials
  std::vector<double> values(box.count() * width);
  std::iota(values.begin(), values.end(), 1.0);
  std::vector<double> whole(kWhole.cell_count() * width, -1.0);
  embed_cells(kWhole, box, values, whole, width);
  std::size_t inside = 0;
  for (std::size_t c = 0; c < kWhole.cell_count(); ++c) {
    const grid::Index3 cell = kWhole.cell_of_index(c);
    bool in = true;
    for (int a = 0; a < 3; ++a) in = in && cell[a] >= box.lo[a] && cell[a] < box.hi[a];
    if (!in) {
      EXPECT_EQ(whole[2 * c], -1.0);
      EXPECT_EQ(whole[2 * c + 1], -1.0);
      continue;
    }
    ++inside;
    // Box grid order: (i - 3) + 3 ((j - 1) + 3 k), two values per cell.
    const std::size_t b =
        static_cast<std::size_t>((cell[0] - 3) + 3 * ((cell[1] - 1) + 3 * cell[2]));
    EXPECT_EQ(whole[2 * c], values[2 * b]);
    EXPECT_EQ(whole[2 * c + 1], values[2 * b + 1]);
  }
  EXPECT_EQ(inside, box.count());
  std::vector<double> back(values.size());
  extract_cells(kWhole, box, whole, back, width);
  EXPECT_EQ(back, values);
}

TEST(SubGrid, WireOrderIsKFastestAndRoundTrips) {
  const grid::Index3 n{3, 4, 5};
  const std::size_t count = 60;
  std::vector<double> grid_order(2 * count);
  std::iota(grid_order.begin(), grid_order.end(), 0.0);
  std::vector<double> wire(grid_order.size());
  grid_to_wire_order(n, grid_order, wire, 2);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 5; ++k) {
        const std::size_t g = i + 3 * (j + 4 * k);  // UniformGrid: x fastest
        const std::size_t w = (i * 4 + j) * 5 + k;  // proto §11: k fastest
        EXPECT_EQ(wire[2 * w], grid_order[2 * g]);
        EXPECT_EQ(wire[2 * w + 1], grid_order[2 * g + 1]);
      }
  std::vector<double> back(grid_order.size());
  wire_to_grid_order(n, wire, back, 2);
  EXPECT_EQ(back, grid_order);

  std::vector<int> materials(count);
  std::iota(materials.begin(), materials.end(), 0);
  std::vector<int> wire_materials(count);
  std::vector<int> materials_back(count);
  grid_to_wire_order(n, std::span<const int>(materials), std::span<int>(wire_materials));
  wire_to_grid_order(n, std::span<const int>(wire_materials), std::span<int>(materials_back));
  EXPECT_EQ(wire_materials[1], 3 * 4);  // wire cell (0, 0, 1) is grid cell 0 + 3 (0 + 4 * 1)
  EXPECT_EQ(materials_back, materials);
}

TEST(SubGrid, WireVectorsRoundTripThroughComponents) {
  const grid::Index3 n{4, 3, 1};
  std::array<std::vector<double>, 3> components;
  for (int a = 0; a < 3; ++a) {
    components[a].resize(12);
    for (std::size_t c = 0; c < 12; ++c) components[a][c] = 100.0 * a + static_cast<double>(c);
  }
  std::vector<double> wire(36);
  grid_to_wire_vectors(n, {components[0], components[1], components[2]}, wire);
  // Wire cell (i, j) = (1, 2) is row 1 * 3 + 2 = 5; grid cell 1 + 4 * 2 = 9.
  EXPECT_EQ(wire[3 * 5 + 0], 9.0);
  EXPECT_EQ(wire[3 * 5 + 2], 209.0);
  std::array<std::vector<double>, 3> back{std::vector<double>(12), std::vector<double>(12),
                                          std::vector<double>(12)};
  wire_to_grid_vectors(n, wire, {back[0], back[1], back[2]});
  EXPECT_EQ(back, components);
}

TEST(SubGrid, SizeMismatchIsAnErrorNamingTheCounts) {
  std::vector<double> wrong(5);
  std::vector<double> out(60);
  EXPECT_THROW(grid_to_wire_order({3, 4, 5}, wrong, out), Error);
  try {
    embed_cells(kWhole, {{0, 0, 0}, {2, 2, 2}}, wrong, out);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("must have 8 values (8 cells x 1), got 5"));
  }
}

}  // namespace
}  // namespace mpfd::coupler::handoff
