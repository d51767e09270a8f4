#include "mpm_solver/sparse_grid.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <set>
#include <vector>

namespace mpfd::mpm {
namespace {

struct Box {
  grid::Index3 lo, hi;
};

TEST(SparseGrid, OnlyTouchedBlocksExistAndNodesAreDistinct) {
  SparseGrid g(grid::UniformGrid::from_bounds({0, 0, 0}, {1, 1, 1}, {40, 40, 40}));
  g.clear();
  g.activate({5, 5, 5}, {6, 6, 6});  // one block
  g.activate({7, 7, 7}, {9, 9, 9});  // crosses into 7 more blocks (4..7 | 8..11 per axis)
  g.allocate_nodes();
  EXPECT_EQ(g.block_count(), 8u);
  EXPECT_EQ(g.block_nodes(), 64u);
  std::set<std::size_t> seen;
  for (int k = 4; k < 12; ++k)
    for (int j = 4; j < 12; ++j)
      for (int i = 4; i < 12; ++i) {
        const std::size_t n = g.node(i, j, k);
        EXPECT_TRUE(seen.insert(n).second);
        const grid::Index3 back = g.node_coordinates(n);
        EXPECT_EQ(back, (grid::Index3{i, j, k}));
      }
  // The next step starts from nothing.
  g.clear();
  g.activate({30, 30, 30}, {30, 30, 30});
  g.allocate_nodes();
  EXPECT_EQ(g.block_count(), 1u);
}

TEST(SparseGrid, SameColourHomeBlocksNeverShareANode) {
  const grid::UniformGrid ug = grid::UniformGrid::from_bounds({0, 0, 0}, {1, 1, 1}, {30, 30, 30});
  SparseGrid g(ug);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> coordinate(0, 29);  // a 3-wide stencil from 0..29 fits
  std::vector<Box> stencils;
  std::vector<std::int32_t> home;
  g.clear();
  for (int p = 0; p < 5000; ++p) {
    const grid::Index3 lo{coordinate(rng), coordinate(rng), coordinate(rng)};
    const grid::Index3 hi{lo[0] + 2, lo[1] + 2, lo[2] + 2};
    stencils.push_back({lo, hi});
    home.push_back(g.activate(lo, hi));
  }
  g.allocate_nodes();
  g.bin_particles(home);
  std::vector<int> count(stencils.size(), 0);
  for (int c = 0; c < SparseGrid::kColours; ++c) {
    std::map<std::size_t, std::int32_t> owner;  // node -> home slot that wrote it
    for (const std::int32_t slot : g.colour(c))
      for (const std::int32_t p : g.bucket(slot)) {
        ++count[static_cast<std::size_t>(p)];
        EXPECT_EQ(home[static_cast<std::size_t>(p)], slot);
        const Box& b = stencils[static_cast<std::size_t>(p)];
        for (int k = b.lo[2]; k <= b.hi[2]; ++k)
          for (int j = b.lo[1]; j <= b.hi[1]; ++j)
            for (int i = b.lo[0]; i <= b.hi[0]; ++i) {
              const auto [it, fresh] = owner.emplace(g.node(i, j, k), slot);
              EXPECT_TRUE(fresh || it->second == slot) << "colour " << c;
            }
      }
  }
  for (const int n : count) EXPECT_EQ(n, 1);  // every particle binned once
}

TEST(SparseGrid, InactiveAxesHaveOneNodeLayer) {
  SparseGrid g(grid::UniformGrid::from_bounds({0, 0, 0}, {1, 0.1, 0.1}, {10, 1, 1}));
  EXPECT_EQ(g.offset(), (grid::Index3{1, 0, 0}));
  g.clear();
  g.activate({0, 0, 0}, {12, 0, 0});  // nodes -1 .. 11: the whole line with ghosts
  g.allocate_nodes();
  EXPECT_EQ(g.block_nodes(), 4u);
  EXPECT_EQ(g.block_count(), 4u);
}

}  // namespace
}  // namespace mpfd::mpm
