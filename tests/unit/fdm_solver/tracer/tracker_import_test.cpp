// A tracker built from imported tracer points (positions and materials only).

#include "fdm_solver/tracer/tracker_import.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::fdm {
namespace {

namespace tm = eos::test_materials;

/// 2D, 6 x 5 cells of 1 cm: products (material 0) in the 3 x 2 lower corner, air elsewhere.
struct Corner {
  grid::UniformGrid g{{0, 0, 0}, {0.01, 0.01, 0.01}, {6, 5, 1}};
  std::vector<double> material, rho, e;
  std::vector<int> fallback;
  Corner() {
    for (int j = 0; j < 5; ++j)
      for (int i = 0; i < 6; ++i) {
        const bool products = i < 3 && j < 2;
        material.push_back(products ? 0.0 : 1.0);
        rho.push_back(products ? 50.0 : tm::kAirDensity);
        e.push_back(products ? 4.0e6 : tm::kAirEnergy);
        fallback.push_back(1);
      }
  }
  MultiMaterialTracker seeded() const { return {g, {tm::kTnt, tm::kAir}, material, rho, e, 3}; }
  MultiMaterialTracker from_points(const TracerSet& points) const {
    return {g, {tm::kTnt, tm::kAir}, tracker_from_points(g, 2, points, fallback, rho, e)};
  }
};

TEST(TrackerImport, TrackerFromPoints_OfSeededTracersEqualsTheSeededTracker) {
  const Corner c;
  MultiMaterialTracker seeded = c.seeded();
  MultiMaterialTracker imported = c.from_points(seeded.tracers());
  EXPECT_EQ(imported.materials().material, seeded.materials().material);
  EXPECT_EQ(imported.materials().theta, seeded.materials().theta);
  EXPECT_EQ(imported.tracers().volume, seeded.tracers().volume);  // V_c / 9, T (3-21)
  EXPECT_EQ(imported.tracers().position, seeded.tracers().position);
  std::vector<double> p_seeded(c.rho.size()), p_imported(c.rho.size());
  seeded.update_pressure(c.rho, c.e, p_seeded);
  imported.update_pressure(c.rho, c.e, p_imported);
  EXPECT_EQ(p_imported, p_seeded);
  EXPECT_EQ(imported.states().energy, seeded.states().energy);
  EXPECT_EQ(imported.states().density, seeded.states().density);
}

TEST(TrackerImport, MovedTracersGiveTheTrackersClassificationWithThetaFromCounts) {
  const Corner c;
  MultiMaterialTracker moving = c.seeded();
  const std::vector<double> u(c.rho.size(), 2.0), v(c.rho.size(), 1.0);
  constexpr TracerBoundaries walls{TracerFace::reflect, TracerFace::reflect, TracerFace::reflect,
                                   TracerFace::reflect, TracerFace::reflect, TracerFace::reflect};
  std::vector<double> p(c.rho.size());
  for (int s = 0; s < 3; ++s) {  // 0.2 and 0.1 cell per step: mixed cells appear
    moving.advect({{u, v, {}}}, 1e-3, walls);
    moving.update_pressure(c.rho, c.e, p);
  }
  const MaterialMap& map = moving.materials();
  std::size_t mixed = 0;
  for (std::size_t cell = 0; cell < map.cell_count(); ++cell) mixed += map.is_mixed(cell) ? 1 : 0;
  ASSERT_GT(mixed, 0u);
  const MultiMaterialTracker imported = c.from_points(moving.tracers());
  EXPECT_EQ(imported.materials().material, map.material);
  const auto& bins = moving.bins();
  for (std::size_t cell = 0; cell < map.cell_count(); ++cell) {
    if (!map.is_mixed(cell)) continue;
    const double counted =
        static_cast<double>(bins.count(cell, 0)) / static_cast<double>(bins.count(cell));
    EXPECT_EQ(imported.materials().volume_fraction(cell, 0), counted) << "cell " << cell;
    EXPECT_DOUBLE_EQ(imported.materials().volume_fraction(cell, 0) +
                         imported.materials().volume_fraction(cell, 1),
                     1.0);
  }
}

TEST(TrackerImport, RefusesATracerOutsideTheGridNamingIt) {
  const Corner c;
  TracerSet points = c.seeded().tracers();
  points.position[1][7] = 0.2;
  try {
    (void)c.from_points(points);
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("tracer 7"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace mpfd::fdm
