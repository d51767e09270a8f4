// V4 (issue 6; T §3.4.3, Fig. 3.11): 3D TNT in free air run by AFDMP; peak
// incident overpressure and arrival time at the scene's gauges against the
// Kingery-Bulmash free-air curves (tests/verification/support). One octant
// [0, 0.25]^3 m with the charge at the origin, so R = |gauge position|.
// Gauges are read as v4_stations.hpp says. KB covers
// Z >= 0.5 m/kg^(1/3): of the scene's gauges x120...x220 and d140...d220 are the
// near field (0.5 <= Z < 1), d260...d380 have Z = 1.10...1.61.
// Fast tier: the equal-mass sphere through the 1D start on 25^3 cells (h = 10 mm).
// Full tier: the sphere (1D start) and the thesis's cube (3D MPM start) on 50^3.
// The figures quoted in the asserts' comments are bench/afdmp/v4_work_precision.sh's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "coupler/run/launch.hpp"
#include "tests/verification/afdmp_v4/v4_stations.hpp"

namespace mpfd::verification {
namespace {

const std::string kConfigs = std::string(MPFD_SOURCE_DIR) + "/configs/";
constexpr double kCubeMass = 0.01304;  // kg: 20 mm cube, 1630 kg/m^3 (T §3.4.3)
// The scenes' end: KB's arrival at the farthest gauge (R = 0.38 m) is 308 us.
constexpr double kEnd = 3.4e-4;

struct V4Run {
  std::vector<Station> stations;  ///< the scene's order
  nlohmann::json summary;
};

/// Runs `config` on cells^3 to kEnd and reads every gauge against KB for `mass`.
V4Run run_v4(const std::string& name, const std::string& config, int cells, double mass) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpfd-afdmp-v4-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ostringstream grid;
  grid << "cells: [" << cells << ", " << cells << ", " << cells << "]";
  const auto yaml = replaced(read_text(kConfigs + config), "cells: [100, 100, 100]", grid.str());
  const auto scene_file = dir / "scene.yaml";
  std::ofstream(scene_file) << yaml;
  const auto out = dir / "out";
  coupler::LaunchOptions launch;  // both solvers in this process
  coupler::CoupledRunOptions options;
  options.out_dir = out;
  options.progress = false;
  coupler::launch_run(scene_file, launch, options, "");

  V4Run run;
  std::ifstream summary(out / "summary.json");
  run.summary = nlohmann::json::parse(summary);
  const auto scene = config::load_scene(scene_file);
  EXPECT_DOUBLE_EQ(scene.time.end, kEnd);
  run.stations = read_stations(out / "gauges.h5", scene, mass, name);
  return run;
}

/// Every handoff's relative conservation errors (sent vs received, solver vs sent).
void expect_handoffs_conserve(const nlohmann::json& summary, double tolerance) {
  const auto& handoffs = summary.at("details").at("afdmp").at("handoffs");
  ASSERT_FALSE(handoffs.empty());
  for (const auto& handoff : handoffs)
    for (const auto& [audit, errors] : handoff.at("relative_error").items())
      for (const auto& [quantity, error] : errors.items())
        EXPECT_LE(error.get<double>(), tolerance)
            << handoff.at("name") << " " << audit << " " << quantity;
}

/// The TNT mass the run holds equals `mass` (0.1 %): the first handoff's FDM
/// totals less the octant's ambient air (1.225 kg/m^3, no charge), TNT at
/// 1630 kg/m^3, times 8 (three mirror planes). The 3D MPM start fills the charge
/// with particles on the grid: exact for the cube where h divides its 10 mm half
/// side (25^3, 50^3, 100^3), not for the sphere (12.23 g on 50^3).
void expect_charge_mass(const nlohmann::json& summary, double mass) {
  const auto& handoff = summary.at("details").at("afdmp").at("handoffs").at(0);
  const double octant_air = 1.225 * 0.25 * 0.25 * 0.25;
  const double octant_tnt =
      (handoff.at("solver_totals").at("mass").get<double>() - octant_air) / (1.0 - 1.225 / 1630.0);
  EXPECT_NEAR(8 * octant_tnt, mass, 1e-3 * mass);
}

/// The stations with Z >= 1 (the far field; KB at its surest).
std::vector<Station> far_field(const V4Run& run) {
  std::vector<Station> far;
  for (const auto& s : run.stations)
    if (s.kb.scaled_distance >= 1.0) far.push_back(s);
  return far;
}

/// Peak overpressure falls with R along each line of gauges (names "x..." and "d...").
void expect_monotone_decay(const V4Run& run) {
  for (const char line : {'x', 'd'}) {
    const Station* previous = nullptr;
    for (const auto& s : run.stations) {
      if (s.gauge.front() != line) continue;
      if (previous) {
        EXPECT_GT(s.distance, previous->distance) << s.gauge;
        EXPECT_LT(s.peak, previous->peak) << s.gauge << " after " << previous->gauge;
      }
      previous = &s;
    }
  }
}

TEST(AfdmpV4, Fast_sphere_1d_start_25_cubed_against_kingery_bulmash) {
  const auto run = run_v4("fast", "afdmp_free_air_3d_1d.yaml", 25, kSphereMass);
  expect_handoffs_conserve(run.summary, 1e-12);
  expect_charge_mass(run.summary, kSphereMass);
  expect_monotone_decay(run);
  const auto far = far_field(run);
  ASSERT_EQ(far.size(), 4U);
  // Measured (h = 10 mm, 6.5 s): peaks -29.6 ... -31.3 % of KB at Z = 1.10 ...
  // 1.61 (the shock is spread over ~3 cells; -24 % at h = 5 mm), arrival
  // -0.5 ... -7.2 % (a smeared shock's foot passes 10 % of the peak early).
  for (const auto& s : far) {
    EXPECT_NEAR(s.peak / s.kb.overpressure, 0.70, 0.05) << s.gauge;
    EXPECT_NEAR(s.arrival / s.kb.arrival_time, 0.96, 0.05) << s.gauge;
  }
}

TEST(AfdmpV4, Full_sphere_1d_start_converges_towards_kingery_bulmash) {
  const auto coarse = run_v4("full-sphere-25", "afdmp_free_air_3d_1d.yaml", 25, kSphereMass);
  const auto fine = run_v4("full-sphere-50", "afdmp_free_air_3d_1d.yaml", 50, kSphereMass);
  // Measured on 50^3: worst 3.05e-12 (solver_vs_sent mass): sums over 125 000
  // cells; the coupler's own tolerance, 1e-12, is exceeded (it warns).
  expect_handoffs_conserve(fine.summary, 1e-11);
  expect_charge_mass(fine.summary, kSphereMass);
  expect_monotone_decay(fine);
  const auto far_coarse = far_field(coarse);
  const auto far_fine = far_field(fine);
  ASSERT_EQ(far_fine.size(), far_coarse.size());
  // Measured (h = 5 mm, 25 s): peaks -22.0 ... -24.9 % of KB at Z = 1.10 ... 1.61
  // (-29.6 ... -31.3 % at h = 10 mm), arrival -3.0 ... +0.3 %. Near field
  // (0.5 <= Z < 1): -12.8 ... -23.4 %.
  for (std::size_t i = 0; i < far_fine.size(); ++i) {
    const auto& s = far_fine[i];
    EXPECT_NEAR(s.peak / s.kb.overpressure, 0.765, 0.04) << s.gauge;
    EXPECT_GT(s.peak, far_coarse[i].peak) << s.gauge << ": no convergence towards KB";
    EXPECT_NEAR(s.arrival / s.kb.arrival_time, 0.985, 0.035) << s.gauge;
  }
}

TEST(AfdmpV4, Full_thesis_cube_mpm_start_against_kingery_bulmash) {
  const auto run = run_v4("full-cube-50", "afdmp_free_air_3d.yaml", 50, kCubeMass);
  // Measured on 50^3: worst 6.7e-12 (sent_vs_received energy), see above.
  expect_handoffs_conserve(run.summary, 1e-11);
  expect_charge_mass(run.summary, kCubeMass);
  expect_monotone_decay(run);
  // Measured (h = 5 mm, 34 s): peaks -18.2 ... -21.8 % of KB at d260 ... d380,
  // arrival +0.3 ... +5.3 %. Before the scene set solver.mpm.reference_pressure,
  // the MPM phase's outflow faces let the air leave (34 m/s at the handoff), p
  // ahead of the shock at d340 and d380 fell 20 % and their peaks read -34 %.
  for (const auto& s : far_field(run)) {
    EXPECT_NEAR(s.peak / s.kb.overpressure, 0.80, 0.04) << s.gauge;
    EXPECT_NEAR(s.arrival / s.kb.arrival_time, 1.025, 0.035) << s.gauge;
  }
}

}  // namespace
}  // namespace mpfd::verification
