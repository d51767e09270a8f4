// Tracer seeding and advection, T (3-13), with the domain faces.

#include "fdm_solver/tracer/tracer_advection.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "common/core/error.hpp"
#include "fdm_solver/tracer/material_map.hpp"
#include "fdm_solver/tracer/tracer_bins.hpp"

namespace mpfd::fdm {
namespace {

using ::testing::HasSubstr;

// Positions are O(1) m sums of a few terms: round-off only.
constexpr double kAdvectionTol = 1e-12;

constexpr TracerBoundaries kOutflowFaces{TracerFace::outflow, TracerFace::outflow,
                                         TracerFace::outflow, TracerFace::outflow,
                                         TracerFace::outflow, TracerFace::outflow};
constexpr TracerBoundaries kReflectFaces{TracerFace::reflect, TracerFace::reflect,
                                         TracerFace::reflect, TracerFace::reflect,
                                         TracerFace::reflect, TracerFace::reflect};

struct UniformField {
  std::array<std::vector<double>, 3> u;
  UniformField(const grid::UniformGrid& g, const grid::Vec3& value) {
    for (int a = 0; a < 3; ++a) u[a].assign(g.cell_count(), value[a]);
  }
  [[nodiscard]] VelocityView view() const { return {{u[0], u[1], u[2]}}; }
};

void expect_n_per_cell(const grid::UniformGrid& g, int n) {
  const std::vector<int> material(g.cell_count(), 0);
  const TracerSet t = seed_from_materials(g, material, n);
  TracerBins bins;
  bins.rebuild(g, t, 1);
  const auto expected = static_cast<std::size_t>(std::pow(n, g.dimension()));
  double volume = 0.0;
  for (std::size_t c = 0; c < g.cell_count(); ++c) EXPECT_EQ(bins.count(c, 0), expected);
  for (const double v : t.volume) volume += v;
  EXPECT_NEAR(volume, g.cell_volume() * static_cast<double>(g.cell_count()),
              kAdvectionTol * volume);  // T (3-21) at seeding
}

TEST(TracerSeeding, PutsNPerActiveAxisInEveryCell) {
  expect_n_per_cell(grid::UniformGrid({0, 0, 0}, {0.1, 1, 1}, {7, 1, 1}), 3);
  expect_n_per_cell(grid::UniformGrid({0, 0, 0}, {0.1, 0.2, 1}, {5, 4, 1}), 3);
  expect_n_per_cell(grid::UniformGrid({0, 0, 0}, {0.1, 0.2, 0.3}, {3, 4, 2}), 2);
}

TEST(TracerSeeding, TracersTakeTheMaterialOfTheirCell) {
  const grid::UniformGrid g({0, 0, 0}, {1, 1, 1}, {4, 1, 1});
  const std::vector<double> material{0, 1, 1, 0};
  const TracerSet t = seed_from_materials(g, material, 2);
  for (std::size_t i = 0; i < t.size(); ++i)
    EXPECT_EQ(t.material[i],
              static_cast<int>(material[static_cast<std::size_t>(std::floor(t.position[0][i]))]));
  EXPECT_THROW((void)seed_from_materials(g, std::vector<double>{0, 0.5, 1, 0}, 2), Error);
}

TEST(TracerAdvection, UniformVelocityMovesEveryTracerByUDt) {
  const grid::UniformGrid g({0, 0, 0}, {0.1, 0.1, 0.1}, {5, 4, 3});
  TracerSet t = seed_from_materials(g, std::vector<int>(g.cell_count(), 0), 2);
  const TracerSet before = t;
  const grid::Vec3 u{30.0, -20.0, 10.0};
  const double dt = 1e-4;  // moves <= 3 mm < 25 mm to the nearest face: nobody leaves
  const AdvectionReport r = advect_tracers(g, UniformField(g, u).view(), dt, kReflectFaces, t);
  ASSERT_EQ(r.removed, 0u);
  ASSERT_EQ(t.size(), before.size());
  for (std::size_t i = 0; i < t.size(); ++i)
    for (int a = 0; a < 3; ++a)
      EXPECT_NEAR(t.position[a][i], before.position[a][i] + u[a] * dt, kAdvectionTol);
}

TEST(TracerAdvection, RigidTranslationByOneCellShiftsCountsAndMaterials) {
  const grid::UniformGrid g({0, 0, 0}, {0.1, 0.1, 1}, {6, 4, 1});
  std::vector<int> material(g.cell_count());
  for (std::size_t c = 0; c < g.cell_count(); ++c) material[c] = g.cell_of_index(c)[0] < 3 ? 0 : 1;
  TracerSet t = seed_from_materials(g, material, 2);
  MaterialMap map(material, 2);
  const UniformField field(g, {0.1 / 4e-3, 0.0, 0.0});  // one cell in 4 steps of 1 ms
  std::size_t removed = 0;
  for (int step = 0; step < 4; ++step)
    removed += advect_tracers(g, field.view(), 1e-3, kOutflowFaces, t).removed;
  EXPECT_EQ(removed, 4u * 4u);  // the last column (4 tracers in each of 4 cells)
  TracerBins bins;
  bins.rebuild(g, t, 2);
  MaterialMap next;
  classify_cells(g, bins, t, map, next);
  for (std::size_t c = 0; c < g.cell_count(); ++c) {
    const int i = g.cell_of_index(c)[0];
    EXPECT_EQ(bins.count(c), i == 0 ? 0u : 4u) << "cell " << c;
    EXPECT_EQ(next.material[c], i <= 3 ? 0 : 1) << "cell " << c;  // cell 0 empty: keeps 0
  }
}

TEST(TracerAdvection, OutflowFaceRemovesAndCountsLeavingTracers) {
  const grid::UniformGrid g({0, 0, 0}, {1, 1, 1}, {4, 1, 1});
  TracerSet t = seed_from_materials(g, std::vector<int>(4, 0), 4);  // at 0.125, 0.375, ...
  // 0.5 m to the right: the two tracers beyond x = 3.5 (3.625, 3.875) leave through x = 4.
  const AdvectionReport r =
      advect_tracers(g, UniformField(g, {5.0, 0, 0}).view(), 0.1, kOutflowFaces, t);
  EXPECT_EQ(r.removed, 2u);
  EXPECT_EQ(t.size(), 14u);
  for (const double x : t.position[0]) EXPECT_LT(x, 4.0);
}

TEST(TracerAdvection, WallFaceReflectsTracersBackInside) {
  const grid::UniformGrid g({0, 0, 0}, {1, 1, 1}, {4, 1, 1});
  TracerSet t;
  t.add({3.9, 0.5, 0.5}, 0, 1.0);
  t.add({0.05, 0.5, 0.5}, 0, 1.0);
  const UniformField right(g, {2.0, 0, 0});
  advect_tracers(g, right.view(), 0.1, kReflectFaces, t);  // 3.9 + 0.2 = 4.1 -> 3.9
  EXPECT_NEAR(t.position[0][0], 3.9, kAdvectionTol);
  const UniformField left(g, {-2.0, 0, 0});
  advect_tracers(g, left.view(), 0.1, kReflectFaces, t);  // 0.25 - 0.2 -> 0.05; 3.9 -> 3.7
  advect_tracers(g, left.view(), 0.1, kReflectFaces, t);  // 0.05 - 0.2 = -0.15 -> 0.15
  EXPECT_EQ(t.size(), 2u);
  EXPECT_NEAR(t.position[0][1], 0.15, kAdvectionTol);
  EXPECT_NEAR(t.position[0][0], 3.5, kAdvectionTol);
}

TEST(TracerAdvection, NonFiniteVelocityThrowsInsteadOfLosingTracers) {
  const grid::UniformGrid g({0, 0, 0}, {1, 1, 1}, {4, 1, 1});
  TracerSet t = seed_from_materials(g, std::vector<int>(4, 0), 1);
  UniformField field(g, {1.0, 0, 0});
  field.u[0][2] = std::nan("");
  try {
    advect_tracers(g, field.view(), 0.1, kOutflowFaces, t);
    FAIL() << "expected mpfd::Error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("non-finite"));
  }
}

}  // namespace
}  // namespace mpfd::fdm
