// Cell classification, tracer volumes and volume fractions, T (3-21)-(3-23).

#include "fdm_solver/tracer/material_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/core/error.hpp"
#include "fdm_solver/tracer/tracer_advection.hpp"

namespace mpfd::fdm {
namespace {

using ::testing::HasSubstr;

// Fractions are sums of a few equal volumes: round-off only.
constexpr double kTolerance = 1e-12;

constexpr TracerBoundaries kAllReflect{TracerFace::reflect, TracerFace::reflect,
                                       TracerFace::reflect, TracerFace::reflect,
                                       TracerFace::reflect, TracerFace::reflect};

/// theta_0 in the cell that a planar interface (initially on the face x = 0.5
/// m, material 0 on the left) reaches after moving 0.37 cell to the right.
double planar_interface_theta(int n, MaterialMap* out = nullptr) {
  const grid::UniformGrid g({0, 0, 0}, {0.1, 0.1, 1}, {10, 4, 1});
  std::vector<int> material(g.cell_count());
  for (std::size_t c = 0; c < g.cell_count(); ++c) material[c] = g.cell_of_index(c)[0] < 5 ? 0 : 1;
  TracerSet t = seed_from_materials(g, material, n);
  const MaterialMap before(material, 2);
  std::array<std::vector<double>, 3> u{
      std::vector<double>(g.cell_count(), 37.0), std::vector<double>(g.cell_count(), 0.0), {}};
  advect_tracers(g, {{u[0], u[1], u[2]}}, 1e-3, kAllReflect, t);  // 0.037 m
  TracerBins bins;
  bins.rebuild(g, t, 2);
  MaterialMap after;
  classify_cells(g, bins, t, before, after);
  if (out) *out = after;
  return after.volume_fraction(g.cell_index(5, 2, 0), 0);
}

TEST(VolumeFraction, PlanarInterfaceConvergesToExactFractionAsTracersPerCellGrow) {
  double first_error = 0.0;
  double last_error = 0.0;
  for (const int n : {2, 4, 8, 16, 32, 64}) {
    const double error = std::abs(planar_interface_theta(n) - 0.37);
    EXPECT_LE(error, 0.5 / n + kTolerance) << n << " tracers per axis";  // one tracer row: 1/n
    (n == 2 ? first_error : last_error) = error;
  }
  EXPECT_LT(last_error, first_error / 10.0);
}

TEST(VolumeFraction, ThetaSumsToOneInEveryCellAndMarksTheInterfaceColumnMixed) {
  MaterialMap map;
  planar_interface_theta(8, &map);
  for (std::size_t c = 0; c < map.cell_count(); ++c) {
    EXPECT_NEAR(map.volume_fraction(c, 0) + map.volume_fraction(c, 1), 1.0, kTolerance);
    EXPECT_EQ(map.is_mixed(c), c % 10 == 5) << "cell " << c;
  }
}

/// One 1D cell with tracers of the given materials and volumes.
struct OneCell {
  grid::UniformGrid g{{0, 0, 0}, {2.0, 1, 1}, {1, 1, 1}};
  TracerSet t;
  TracerBins bins;
  OneCell(const std::vector<int>& material, const std::vector<double>& volume, int count) {
    for (std::size_t i = 0; i < material.size(); ++i)
      t.add({0.1 + 0.1 * static_cast<double>(i), 0.5, 0.5}, material[i], volume[i]);
    bins.rebuild(g, t, count);
  }
};

TEST(VolumeFraction, Eq323IsTheCarriedVolumeShare) {
  OneCell cell({0, 1, 1, 0, 1}, {0.1, 0.2, 0.3, 0.4, 0.5}, 2);
  MaterialMap map;
  classify_cells(cell.g, cell.bins, cell.t, MaterialMap(std::vector<int>{0}, 2), map);
  ASSERT_TRUE(map.is_mixed(0));
  EXPECT_NEAR(map.volume_fraction(0, 0), (0.1 + 0.4) / 1.5, kTolerance);  // T (3-23)
  EXPECT_NEAR(map.volume_fraction(0, 1), (0.2 + 0.3 + 0.5) / 1.5, kTolerance);
}

TEST(TracerVolume, Eq321And322ShareTheCellVolume) {
  OneCell mixed({0, 1, 1, 0, 1}, {1, 1, 1, 1, 1}, 2);
  MaterialMap map(std::vector<int>{0}, 2);
  map.material[0] = kMixedCell;
  map.theta = {0.3, 0.7};
  assign_tracer_volumes(mixed.g, mixed.bins, map, mixed.t);
  for (std::size_t i = 0; i < mixed.t.size(); ++i)  // T (3-22): theta_r V_c / n_br
    EXPECT_NEAR(mixed.t.volume[i], mixed.t.material[i] == 0 ? 0.3 * 2.0 / 2 : 0.7 * 2.0 / 3,
                kTolerance);
  OneCell single({1, 1, 1, 1}, {9, 9, 9, 9}, 2);
  assign_tracer_volumes(single.g, single.bins, MaterialMap(std::vector<int>{1}, 2), single.t);
  for (const double v : single.t.volume) EXPECT_NEAR(v, 2.0 / 4, kTolerance);  // T (3-21)
}

TEST(Classification, EmptyCellKeepsItsPreviousMaterialAndFractions) {
  OneCell empty({}, {}, 2);
  MaterialMap previous(std::vector<int>{0}, 2);
  previous.material[0] = kMixedCell;
  previous.theta = {0.25, 0.75};
  MaterialMap next;
  classify_cells(empty.g, empty.bins, empty.t, previous, next);
  EXPECT_TRUE(next.is_mixed(0));
  EXPECT_EQ(next.theta, previous.theta);
}

TEST(Classification, ThreeMaterialsInOneCellThrowNamingTheCell) {
  const grid::UniformGrid g({0, 0, 0}, {1, 1, 1}, {3, 2, 1});
  TracerSet t;
  for (const int m : {0, 1, 2}) t.add({2.5, 1.5, 0.5}, m, 1.0);  // cell (2, 1, 0)
  TracerBins bins;
  bins.rebuild(g, t, 3);
  MaterialMap next;
  try {
    classify_cells(g, bins, t, MaterialMap(std::vector<int>(6, 0), 3), next);
    FAIL() << "expected mpfd::Error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("cell (2, 1, 0)"));
    EXPECT_THAT(e.what(), HasSubstr("materials 0, 1, 2"));
  }
}

}  // namespace
}  // namespace mpfd::fdm
