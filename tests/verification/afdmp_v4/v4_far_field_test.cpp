// V4 far field (issue 6): the 13.05 g TNT sphere of configs/afdmp_free_air_3d_far.yaml,
// detonated in the 1D spherical MPM (seed S) until its front reaches 0.2 m, then
// carried by the FDM on the octant [0, 1.25]^3 m; gauges on the x axis and the
// diagonal at Z = 0.5 ... 5 m/kg^(1/3) (Z = 0.5 and 0.75 are read from the 1D
// stage). Peak incident overpressure and arrival against Kingery-Bulmash
// (tests/verification/support), gauges read as v4_stations.hpp says.
// Fast tier: the octant on 50^3 cells (h = 25 mm).
// Full tier: 50^3 and 80^3 (h = 15.625 mm), and the 1D reference
// configs/afdmp_free_air_1d_reference.yaml (the 1D MPM alone to R = 1.3 m).
// The figures in the asserts' comments are bench/afdmp/v4_far.sh's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "coupler/run/launch.hpp"
#include "mpm_solver/spherical/spherical_run.hpp"
#include "tests/verification/afdmp_v4/v4_stations.hpp"

namespace mpfd::verification {
namespace {

namespace fs = std::filesystem;

const fs::path kConfigDir = fs::path(MPFD_SOURCE_DIR) / "configs";

struct FarRun {
  std::vector<Station> stations;  ///< the scene's order
  nlohmann::json summary;
  double handoff_radius = 0;  ///< m, the scene's solver.afdmp.spherical.handoff_radius
};

/// The far octant on cells^3; switch_power: solver.fdm.viscosity_switch_power.
FarRun run_far(int cells, int switch_power = 1) {
  const std::string name = "far-" + std::to_string(cells) + "-p" + std::to_string(switch_power);
  const auto dir = fs::temp_directory_path() / ("mpfd-afdmp-v4-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string grid = "cells: [" + std::to_string(cells) + ", " + std::to_string(cells) +
                           ", " + std::to_string(cells) + "]";
  const auto scene_file = dir / "scene.yaml";
  std::string text = replaced(read_text(kConfigDir / "afdmp_free_air_3d_far.yaml"),
                              "cells: [125, 125, 125]", grid);
  if (switch_power != 1)
    text = replaced(
        text, "  method: afdmp\n",
        "  method: afdmp\n  fdm: {viscosity_switch_power: " + std::to_string(switch_power) + "}\n");
  std::ofstream(scene_file) << text;
  coupler::LaunchOptions launch;  // both solvers in this process
  launch.timeout_seconds = 600;   // s: an FDM step of 5e5 cells exceeds 5 s on a loaded machine
  coupler::CoupledRunOptions options;
  options.out_dir = dir / "out";
  options.progress = false;
  coupler::launch_run(scene_file, launch, options, "");
  FarRun run;
  std::ifstream summary(dir / "out" / "summary.json");
  run.summary = nlohmann::json::parse(summary);
  const auto scene = config::load_scene(scene_file);
  run.stations = read_stations(dir / "out" / "gauges.h5", scene, kSphereMass, name);
  run.handoff_radius = scene.solver.afdmp.spherical.handoff_radius.value();
  return run;
}

/// The stations the FDM carries: beyond the handoff radius (Z = 1 ... 5).
std::vector<Station> fdm_stations(const FarRun& run) {
  std::vector<Station> out;
  for (const auto& s : run.stations)
    if (s.distance > run.handoff_radius) out.push_back(s);
  return out;
}

void expect_handoff_conserves(const nlohmann::json& summary, double tolerance) {
  const auto& handoffs = summary.at("details").at("afdmp").at("handoffs");
  ASSERT_EQ(handoffs.size(), 1U);
  for (const auto& [audit, errors] : handoffs[0].at("relative_error").items())
    for (const auto& [quantity, error] : errors.items())
      EXPECT_LE(error.get<double>(), tolerance) << audit << " " << quantity;
}

/// Peak overpressure falls with R along each line of gauges ("x...", "d..." and
/// the 1D reference's "z...").
void expect_monotone_decay(const std::vector<Station>& stations) {
  for (const char line : {'x', 'd', 'z'}) {
    const Station* previous = nullptr;
    for (const auto& s : stations) {
      if (s.gauge.front() != line) continue;
      if (previous) {
        EXPECT_LT(s.peak, previous->peak) << s.gauge << " after " << previous->gauge;
      }
      previous = &s;
    }
  }
}

TEST(AfdmpV4Far, Fast_octant_to_z5_on_50_cubed) {
  const auto run = run_far(50);
  expect_handoff_conserves(run.summary, 1e-11);
  expect_monotone_decay(run.stations);
  const auto far = fdm_stations(run);
  ASSERT_EQ(far.size(), 12U);
  // Measured (h = 25 mm, 16 s): peaks -39.6 ... -57.8 % of KB at Z = 1 ... 5 (the
  // handoff's conservative cell averages spread the thin shock of R = 0.2 m over
  // cells 25 mm wide; the FDM never regains the spike), arrival -18.0 ... -1.9 %
  // (the smeared front passes 10 % of its peak early).
  for (const auto& s : far) {
    EXPECT_NEAR(s.peak / s.kb.overpressure, 0.51, 0.1) << s.gauge;
    EXPECT_NEAR(s.arrival / s.kb.arrival_time, 0.91, 0.1) << s.gauge;
  }
}

// docs/fdm.md's switch power reaches the coupled FDM through the scene: at
// p = 2 every FDM gauge reads a higher peak. Measured (h = 25 mm): mean peak vs
// KB over Z = 1 ... 5 -48.3 % at p = 1, -37.9 % at p = 2 (range -54.2 ... -26.0 %).
TEST(AfdmpV4Far, Fast_switch_power_2_raises_every_far_peak_on_50_cubed) {
  const auto thesis = fdm_stations(run_far(50));
  const auto squared_run = run_far(50, 2);
  expect_handoff_conserves(squared_run.summary, 1e-11);
  expect_monotone_decay(squared_run.stations);
  const auto squared = fdm_stations(squared_run);
  ASSERT_EQ(squared.size(), thesis.size());
  double thesis_error = 0, squared_error = 0;
  for (std::size_t i = 0; i < squared.size(); ++i) {
    EXPECT_GT(squared[i].peak, thesis[i].peak) << squared[i].gauge;
    thesis_error += thesis[i].peak / thesis[i].kb.overpressure - 1;
    squared_error += squared[i].peak / squared[i].kb.overpressure - 1;
  }
  const auto gauges = static_cast<double>(squared.size());
  EXPECT_NEAR(squared_error / gauges, -0.38, 0.05);
  EXPECT_GT((squared_error - thesis_error) / gauges, 0.05);
}

TEST(AfdmpV4Far, Full_octant_converges_towards_the_1d_reference) {
  const auto coarse = run_far(50);
  const auto fine = run_far(80);
  expect_handoff_conserves(fine.summary, 1e-11);
  expect_monotone_decay(fine.stations);
  const auto far_coarse = fdm_stations(coarse);
  const auto far_fine = fdm_stations(fine);
  ASSERT_EQ(far_fine.size(), far_coarse.size());
  // Measured (h = 15.625 mm, 2 min): peaks -30.3 ... -47.9 % of KB at Z = 1 ... 5,
  // arrival -13.8 ... +1.1 %.
  for (std::size_t i = 0; i < far_fine.size(); ++i) {
    const auto& s = far_fine[i];
    EXPECT_NEAR(s.peak / s.kb.overpressure, 0.61, 0.1) << s.gauge;
    EXPECT_GT(s.peak, far_coarse[i].peak) << s.gauge << ": no convergence";
    EXPECT_NEAR(s.arrival / s.kb.arrival_time, 0.97, 0.12) << s.gauge;
  }
}

TEST(AfdmpV4Far, Full_1d_reference_against_kingery_bulmash) {
  const fs::path file = kConfigDir / "afdmp_free_air_1d_reference.yaml";
  const auto scene = config::load_scene(file);
  const fs::path out = fs::temp_directory_path() / "mpfd-afdmp-v4-1d-reference";
  mpm::spherical::run_spherical(scene, {file, out, true});
  const auto stations = read_stations(out / "gauges.h5", scene, kSphereMass, "1d", true);
  ASSERT_EQ(stations.size(), 8U);
  expect_monotone_decay(stations);
  // Measured (h = 0.62 mm, 58-100 s): peaks +11 ... +32 % of KB at Z = 0.5 ... 5, the
  // maxima of the MPM's ringing behind the shock (+-30 % at Z = 1; the largest
  // mean over 8 cells' passage reads -5 ... -21 %), arrival -1.1 ... +2.9 %.
  for (const auto& s : stations) {
    EXPECT_NEAR(s.peak / s.kb.overpressure, 1.21, 0.12) << s.gauge;
    EXPECT_NEAR(s.arrival / s.kb.arrival_time, 1.0, 0.04) << s.gauge;
  }
}

}  // namespace
}  // namespace mpfd::verification
