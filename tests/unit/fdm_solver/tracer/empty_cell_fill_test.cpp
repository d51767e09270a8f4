#include "fdm_solver/tracer/empty_cell_fill.hpp"

#include <gtest/gtest.h>

#include <random>

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

/// The fill as first written: breadth-first over Index3 neighbours. The
/// solver's must label every cell the same (ties included).
void reference_fill(const grid::UniformGrid& grid, const TracerBins& bins, MaterialMap& map) {
  const std::size_t cells = grid.cell_count();
  std::vector<std::size_t> queue;
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) == 0) map.material[c] = -2;
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) > 0) queue.push_back(c);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    int material = map.material[c];
    if (map.is_mixed(c)) material = map.volume_fraction(c, 1) > map.volume_fraction(c, 0) ? 1 : 0;
    const grid::Index3 cell = grid.cell_of_index(c);
    for (int a = 0; a < 3; ++a) {
      if (!grid.is_active(a)) continue;
      for (const int step : {-1, 1}) {
        grid::Index3 next = cell;
        next[a] += step;
        if (next[a] < 0 || next[a] >= grid.cells()[a]) continue;
        const std::size_t n = grid.cell_index(next);
        if (map.material[n] != -2) continue;
        map.material[n] = material;
        queue.push_back(n);
      }
    }
  }
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) == 0)
      for (int r = 0; r < 2; ++r)
        map.theta[static_cast<std::size_t>(r) * cells + c] = r == map.material[c] ? 1.0 : 0.0;
}

// Random sparse tracers of two materials on 3D grids and 2D ones in each plane,
// with mixed cells among the sources: every empty cell gets the reference's
// material and volume fractions.
TEST(EmptyCellFill, LabelsEveryCellAsTheFirstWrittenBreadthFirstFill) {
  std::mt19937 random(7);
  for (const grid::Index3 shape : {grid::Index3{9, 7, 5}, grid::Index3{12, 8, 1},
                                   grid::Index3{1, 9, 7}, grid::Index3{7, 1, 5}}) {
    const grid::UniformGrid grid{{0, 0, 0}, {1, 1, 1}, shape};  // cells of 1 m
    const std::size_t cells = grid.cell_count();
    for (int trial = 0; trial < 20; ++trial) {
      TracerSet tracers;
      std::uniform_real_distribution<double> unit(0.0, 1.0);
      const int count = 1 + trial * 3;
      for (int t = 0; t < count; ++t)
        tracers.add({shape[0] * unit(random), shape[1] * unit(random), shape[2] * unit(random)},
                    unit(random) < 0.5 ? 0 : 1, 1.0);
      TracerBins bins;
      bins.rebuild(grid, tracers, 2);
      std::vector<int> start(cells, 0);
      MaterialMap map{start, 2};
      for (std::size_t c = 0; c < cells; ++c) {
        if (bins.count(c) == 0) continue;
        const double theta1 =
            static_cast<double>(bins.count(c, 1)) / static_cast<double>(bins.count(c));
        map.material[c] = theta1 == 0.0 ? 0 : theta1 == 1.0 ? 1 : kMixedCell;
        map.theta[c] = 1.0 - theta1;
        map.theta[cells + c] = theta1;
      }
      MaterialMap expected = map;
      reference_fill(grid, bins, expected);
      std::vector<std::size_t> queue;
      fill_empty_cells(grid, bins, map, queue);
      EXPECT_EQ(map.material, expected.material) << "trial " << trial;
      EXPECT_EQ(map.theta, expected.theta) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace mpfd::fdm
