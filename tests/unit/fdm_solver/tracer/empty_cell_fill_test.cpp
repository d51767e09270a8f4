#include "fdm_solver/tracer/empty_cell_fill.hpp"

#include <gtest/gtest.h>

namespace mpfd::fdm {
namespace {

/// A row of 6 cells of 1 m: tracers of material 1 in cells 0-1 and of
/// material 0 in cell 5; cells 2-4 are empty and were all material 0 before.
struct Row {
  grid::UniformGrid grid{{0, 0, 0}, {1, 1, 1}, {6, 1, 1}};
  TracerSet tracers;
  TracerBins bins;
  MaterialMap map{std::vector<int>{1, 1, 0, 0, 0, 0}, 2};
  std::vector<std::size_t> queue;

  Row() {
    tracers.add({0.5, 0.5, 0.5}, 1, 1.0);
    tracers.add({1.5, 0.5, 0.5}, 1, 1.0);
    tracers.add({5.5, 0.5, 0.5}, 0, 1.0);
    bins.rebuild(grid, tracers, 2);
  }
};

TEST(EmptyCellFill, EmptyCellsTakeTheMaterialOfTheNearestTracers) {
  Row row;
  fill_empty_cells(row.grid, row.bins, row.map, row.queue);
  EXPECT_EQ(row.map.material[2], 1);  // next to the expanded material 1
  EXPECT_EQ(row.map.material[4], 0);  // next to material 0's tracers
  EXPECT_EQ(row.map.material[3], 1);  // equidistant: the lower source cell wins, every time
  for (std::size_t c = 0; c < 6; ++c)
    EXPECT_DOUBLE_EQ(row.map.theta[c] + row.map.theta[6 + c], 1.0) << c;
  EXPECT_DOUBLE_EQ(row.map.theta[6 + 2], 1.0);  // theta of material 1 in cell 2
}

TEST(EmptyCellFill, CellsHoldingTracersAreUntouched) {
  Row row;
  const MaterialMap before = row.map;
  fill_empty_cells(row.grid, row.bins, row.map, row.queue);
  for (const std::size_t c : {0u, 1u, 5u}) EXPECT_EQ(row.map.material[c], before.material[c]);
}

TEST(EmptyCellFill, AGridWithoutTracersKeepsItsPreviousMaterials) {
  Row row;
  row.tracers = TracerSet{};
  row.bins.rebuild(row.grid, row.tracers, 2);
  const MaterialMap before = row.map;
  fill_empty_cells(row.grid, row.bins, row.map, row.queue);
  EXPECT_EQ(row.map.material, before.material);
}

}  // namespace
}  // namespace mpfd::fdm
