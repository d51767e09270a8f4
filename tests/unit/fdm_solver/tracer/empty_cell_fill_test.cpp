#include "fdm_solver/tracer/empty_cell_fill.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::fdm {
namespace {

/// A row of 6 cells of 1 m: tracers of material 1 in cells 0-1 and of
/// material 0 in cell 5; cells 2-4 are empty and were all material 0 before.
struct Row {
  grid::UniformGrid grid{{0, 0, 0}, {1, 1, 1}, {6, 1, 1}};
  TracerSet tracers;
  TracerBins bins;
  MaterialMap previous{std::vector<int>{1, 1, 0, 0, 0, 0}, 2};
  MaterialMap map = previous;  // as classify_cells leaves it: the empty cells as before
  FillScratch scratch;

  Row() {
    tracers.add({0.5, 0.5, 0.5}, 1, 1.0);
    tracers.add({1.5, 0.5, 0.5}, 1, 1.0);
    tracers.add({5.5, 0.5, 0.5}, 0, 1.0);
    bins.rebuild(grid, tracers, 2);
  }
};

TEST(EmptyCellFill, AnEmptyCellWhereMaterialsMetTakesTheNearestKnownMaterial) {
  Row row;
  fill_empty_cells(row.grid, row.bins, &row.previous, 1.0, row.map, row.scratch);
  EXPECT_EQ(row.map.material[2], 1);  // next to the expanding material 1's tracers
  for (std::size_t c = 0; c < 6; ++c)
    EXPECT_DOUBLE_EQ(row.map.theta[c] + row.map.theta[6 + c], 1.0) << c;
  EXPECT_DOUBLE_EQ(row.map.theta[6 + 2], 1.0);  // theta of material 1 in cell 2
}

TEST(EmptyCellFill, AnEmptyCellInsideOneMaterialKeepsIt) {
  Row row;
  fill_empty_cells(row.grid, row.bins, &row.previous, 1.0, row.map, row.scratch);
  // Cells 3 and 4 and both their neighbours were material 0: material 1, two cells
  // away, cannot reach them in one step (the nearest-tracer fill gave cell 3 material 1).
  EXPECT_EQ(row.map.material[3], 0);
  EXPECT_EQ(row.map.material[4], 0);
  EXPECT_DOUBLE_EQ(row.map.theta[3], 1.0);
}

TEST(EmptyCellFill, CellsHoldingTracersAreUntouched) {
  Row row;
  const MaterialMap before = row.map;
  fill_empty_cells(row.grid, row.bins, &row.previous, 1.0, row.map, row.scratch);
  for (const std::size_t c : {0u, 1u, 5u}) EXPECT_EQ(row.map.material[c], before.material[c]);
}

TEST(EmptyCellFill, AGridWithoutTracersKeepsItsPreviousMaterials) {
  Row row;
  row.tracers = TracerSet{};
  row.bins.rebuild(row.grid, row.tracers, 2);
  const MaterialMap before = row.map;
  fill_empty_cells(row.grid, row.bins, &row.previous, 1.0, row.map, row.scratch);
  EXPECT_EQ(row.map.material, before.material);
}

// The V4 1D start at 100^3 (2026-12-07): a products tracer cell standing out of the
// cloud's surface labelled the whole line of far air beyond it as products, whose
// equation of state then gave that air 76 kPa. A 20 x 5 x 5 grid: products (1) filled
// x < 5 before the step, air (0) the rest; after it, products tracers in x < 5 and in
// cell (5, 2, 2), air tracers in the other cells of x = 5.
/// The far-air case below: 20 x 5 x 5 cells, products (1) filled x < 5 before the step,
/// air (0) the rest; after it, products tracers in x < 5 and in cell (5, 2, 2), air
/// tracers in the other cells of x = 5. Returns the filled map for tracers that moved
/// up to `cells_moved` cells.
MaterialMap protruding_products(double cells_moved) {
  const grid::UniformGrid grid{{0, 0, 0}, {1, 1, 1}, {20, 5, 5}};  // cells of 1 m
  const std::size_t cells = grid.cell_count();
  std::vector<int> before(cells, 0);
  TracerSet tracers;
  for (std::size_t c = 0; c < cells; ++c) {
    const grid::Index3 at = grid.cell_of_index(c);
    if (at[0] < 5) before[c] = 1;
    const grid::Vec3 centre{at[0] + 0.5, at[1] + 0.5, at[2] + 0.5};
    if (at[0] < 5) tracers.add(centre, 1, 1.0);
    if (at[0] == 5) tracers.add(centre, at[1] == 2 && at[2] == 2 ? 1 : 0, 1.0);
  }
  TracerBins bins;
  bins.rebuild(grid, tracers, 2);
  const MaterialMap previous{before, 2};
  MaterialMap map;
  classify_cells(grid, bins, tracers, previous, map);
  FillScratch scratch;
  fill_empty_cells(grid, bins, &previous, cells_moved, map, scratch);
  return map;
}

std::size_t cell(int i) {
  return static_cast<std::size_t>(i + 20 * (2 + 5 * 2));
}  // (i, 2, 2)

// The V4 1D start at 100^3 (2026-12-07): a products tracer cell standing out of the
// cloud's surface labelled the whole line of far air beyond it as products, whose
// equation of state then gave that air 76 kPa.
TEST(EmptyCellFill, FarAirBeyondAProtrudingProductsCellStaysAir) {
  const MaterialMap map = protruding_products(0.6);
  for (int i = 6; i < 20; ++i) EXPECT_EQ(map.material[cell(i)], 0) << "cell (" << i << ", 2, 2)";
}

// Tracers that moved 1.5 cells (cfl 0.75 behind a strong shock): the cell beside the
// protruding one is within reach of the products that were at x < 5, so it is filled
// (from the protruding products cell); the air beyond that reach stays air.
TEST(EmptyCellFill, ATracerMovedFartherWidensTheFilledBandToItsReach) {
  const MaterialMap map = protruding_products(1.5);
  EXPECT_EQ(map.material[cell(6)], 1);
  for (int i = 7; i < 20; ++i) EXPECT_EQ(map.material[cell(i)], 0) << "cell (" << i << ", 2, 2)";
}

// A step that moved a tracer farther than the fill looks (kMaxFillReach) was longer
// than the FDM's stable dt: refused, naming the move, not filled from a neighbourhood
// the fill did not read.
TEST(EmptyCellFill, AMoveBeyondTheFillsReachIsRefused) {
  EXPECT_NO_THROW(protruding_products(kMaxFillReach));
  try {
    protruding_products(kMaxFillReach + 0.25);
    FAIL() << "a move of 4.25 cells was filled";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("a tracer moved 4.25 cells"), std::string::npos)
        << error.what();
  }
}

// An import has no step before it: every empty cell takes the nearest known material,
// whatever the fallback classification said.
TEST(EmptyCellFill, AtAnImportEveryEmptyCellIsFilled) {
  Row row;
  fill_empty_cells(row.grid, row.bins, nullptr, 0.0, row.map, row.scratch);
  EXPECT_EQ(row.map.material[2], 1);
  EXPECT_EQ(row.map.material[3], 1);  // equidistant: the lower source cell wins, every time
  EXPECT_EQ(row.map.material[4], 0);
}

/// The fill written plainly: Index3 neighbourhoods, the same rule and visiting order.
/// The solver's must label every cell the same (ties included).
void reference_fill(const grid::UniformGrid& grid, const TracerBins& bins,
                    const MaterialMap* previous_map, int reach, MaterialMap& map) {
  const std::size_t cells = grid.cell_count();
  const auto inside = [&](std::size_t c) {
    if (previous_map == nullptr) return false;
    const MaterialMap& previous = *previous_map;
    if (previous.is_mixed(c)) return false;
    const grid::Index3 cell = grid.cell_of_index(c);
    for (int dk = -reach; dk <= reach; ++dk)
      for (int dj = -reach; dj <= reach; ++dj)
        for (int di = -reach; di <= reach; ++di) {
          const grid::Index3 n{cell[0] + di, cell[1] + dj, cell[2] + dk};
          bool in_grid = true;
          for (int a = 0; a < 3; ++a) in_grid = in_grid && n[a] >= 0 && n[a] < grid.cells()[a];
          if (in_grid && previous.material[grid.cell_index(n)] != previous.material[c])
            return false;
        }
    return true;
  };
  const auto neighbours = [&](std::size_t c) {
    std::vector<std::size_t> out;
    const grid::Index3 cell = grid.cell_of_index(c);
    for (int a = 0; a < 3; ++a)
      for (const int step : {-1, 1}) {
        grid::Index3 next = cell;
        next[a] += step;
        if (next[a] >= 0 && next[a] < grid.cells()[a]) out.push_back(grid.cell_index(next));
      }
    return out;
  };
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) == 0 && !inside(c)) map.material[c] = -2;
  std::vector<std::size_t> queue;
  for (std::size_t c = 0; c < cells; ++c) {
    if (map.material[c] == -2) continue;
    for (const std::size_t n : neighbours(c))
      if (map.material[n] == -2) {
        queue.push_back(c);
        break;
      }
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const std::size_t c = queue[head];
    int material = map.material[c];
    if (map.is_mixed(c)) material = map.volume_fraction(c, 1) > map.volume_fraction(c, 0) ? 1 : 0;
    for (const std::size_t n : neighbours(c)) {
      if (map.material[n] != -2) continue;
      map.material[n] = material;
      queue.push_back(n);
    }
  }
  for (std::size_t c = 0; c < cells; ++c)
    if (bins.count(c) == 0)
      for (int r = 0; r < 2; ++r)
        map.theta[static_cast<std::size_t>(r) * cells + c] = r == map.material[c] ? 1.0 : 0.0;
}

// Random sparse tracers of two materials on 3D grids and 2D ones in each plane, over
// a random earlier classification with mixed cells: every empty cell gets the
// reference's material and volume fractions.
TEST(EmptyCellFill, LabelsEveryCellAsThePlainlyWrittenFill) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const grid::Index3 shape : {grid::Index3{9, 7, 5}, grid::Index3{12, 8, 1},
                                   grid::Index3{1, 9, 7}, grid::Index3{7, 1, 5}}) {
    const grid::UniformGrid grid{{0, 0, 0}, {1, 1, 1}, shape};  // cells of 1 m
    const std::size_t cells = grid.cell_count();
    for (int trial = 0; trial < 20; ++trial) {
      // Before the step: material 1 below a random plane x + y + z < cut, a few mixed cells.
      const double cut = (shape[0] + shape[1] + shape[2]) * unit(random);
      std::vector<int> before(cells);
      for (std::size_t c = 0; c < cells; ++c) {
        const grid::Index3 at = grid.cell_of_index(c);
        before[c] = at[0] + at[1] + at[2] < cut ? 1 : 0;
      }
      MaterialMap previous{before, 2};
      for (std::size_t c = 0; c < cells; ++c)
        if (unit(random) < 0.05) {
          previous.material[c] = kMixedCell;
          previous.theta[c] = previous.theta[cells + c] = 0.5;
        }
      TracerSet tracers;
      const int count = 1 + trial * 3;
      for (int t = 0; t < count; ++t)
        tracers.add({shape[0] * unit(random), shape[1] * unit(random), shape[2] * unit(random)},
                    unit(random) < 0.5 ? 0 : 1, 1.0);
      TracerBins bins;
      bins.rebuild(grid, tracers, 2);
      MaterialMap classified;
      classify_cells(grid, bins, tracers, previous, classified);
      // Tracers that moved 0.3, 1, 1.7 and 2.5 cells (reach 1, 1, 2, 3), and an import.
      for (const double moved : {0.3, 1.0, 1.7, 2.5, -1.0}) {
        const bool import = moved < 0;
        MaterialMap expected = classified;
        reference_fill(grid, bins, import ? nullptr : &previous,
                       std::max(1, static_cast<int>(std::ceil(moved))), expected);
        MaterialMap map = classified;
        FillScratch scratch;
        fill_empty_cells(grid, bins, import ? nullptr : &previous, moved, map, scratch);
        EXPECT_EQ(map.material, expected.material) << "trial " << trial << ", moved " << moved;
        EXPECT_EQ(map.theta, expected.theta) << "trial " << trial << ", moved " << moved;
      }
    }
  }
}

}  // namespace
}  // namespace mpfd::fdm
