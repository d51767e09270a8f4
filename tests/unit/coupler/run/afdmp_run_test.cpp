// AFDMP runs (coupler/run/afdmp_run.hpp) with the real solvers, on coarse
// versions of the V3, V4 (1D start) and V5 scenes: phases change at their
// triggers, every handoff conserves mass, momentum and energy to round-off
// (three ways: what the coupler received, sent, and the importer holds), and
// the chunk size of the whole-field transfers does not change the result.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "common/core/error.hpp"
#include "coupler/run/launch.hpp"
#include "coupler/run/replay.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::HasSubstr;

constexpr double kRoundOff = 1e-12;  // relative; sums of up to 1e5 values

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// configs/<name>.yaml with `from` -> `to` replacements, written under a fresh folder.
std::filesystem::path scene_variant(const std::string& name, const std::string& tag,
                                    const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = read_text(std::filesystem::path(MPFD_CONFIGS) / (name + ".yaml"));
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw Error("test scene edit: '" + from + "' not in " + name);
    text.replace(at, from.size(), to);
  }
  const auto dir = std::filesystem::temp_directory_path() / ("mpfd-afdmp-test-" + tag);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scene.yaml") << text;
  return dir / "scene.yaml";
}

nlohmann::json run(const std::filesystem::path& scene, const std::string& out_name,
                   std::uint64_t chunk_bytes = std::uint64_t{64} << 20,
                   LaunchMode mode = LaunchMode::embedded,
                   const std::optional<std::filesystem::path>& record = std::nullopt) {
  LaunchOptions launch;
  launch.mode = mode;
  launch.overwrite = true;
  launch.fdm_program = MPFD_FDM_SOLVER;
  launch.mpm_program = MPFD_MPM_SOLVER;
  CoupledRunOptions options;
  options.out_dir = scene.parent_path() / out_name;
  options.progress = false;
  options.max_chunk_bytes = chunk_bytes;
  options.record = record;
  (void)launch_run(scene, launch, options, MPFD_FDM_SOLVER);
  std::ifstream in(options.out_dir / "summary.json");
  return nlohmann::json::parse(in);
}

/// Every relative error of every handoff is round-off (these grids are small
/// enough for 1e-12; the run's own bound, `tolerance`, grows with the values summed).
void expect_round_off(const nlohmann::json& handoff) {
  EXPECT_GE(handoff["tolerance"].get<double>(), kRoundOff);
  for (const auto& [comparison, errors] : handoff["relative_error"].items())
    for (const auto& [quantity, value] : errors.items())
      EXPECT_LE(value.get<double>(), kRoundOff)
          << handoff["name"] << " " << comparison << " " << quantity;
}

std::vector<std::string> phase_names(const nlohmann::json& summary) {
  std::vector<std::string> names;
  for (const auto& phase : summary["details"]["afdmp"]["phases"]) names.push_back(phase["phase"]);
  return names;
}

// V3 at h = 10 mm (T §3.4.2): the MPM detonates the r = 50 mm charge, then the FDM.
const std::vector<std::pair<std::string, std::string>> kV3Fast = {
    {"cells: [500, 500, 1]", "cells: [50, 50, 1]"}, {"end: 9.0e-5", "end: 3.0e-5"}};

TEST(AfdmpRun, The_MPM_hands_the_blast_to_the_FDM_when_the_charge_has_burnt) {
  const auto scene = scene_variant("afdmp_blast_2d", "v3", kV3Fast);
  const auto summary = run(scene, "out");
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_THAT(phase_names(summary), ::testing::ElementsAre("mpm_detonation", "fdm_blast", "done"));
  const auto& handoffs = summary["details"]["afdmp"]["handoffs"];
  ASSERT_EQ(handoffs.size(), 1u);
  EXPECT_EQ(handoffs[0]["name"], "mpm_to_fdm");
  expect_round_off(handoffs[0]);
  // Program burn, T (3-1), (3-2): the last particle (r = 47.5 mm, particle
  // spacing h_p = 5 mm) lights at r / D and reaches F = 1 after 1.5 h_p / D.
  const double D = 6930, lit = 0.0475 / D, burnt = lit + 1.5 * 0.005 / D;
  const double t = handoffs[0]["time"];
  EXPECT_GE(t, burnt * (1 - 1e-9));
  EXPECT_LE(t, burnt + 1.0e-6);  // within one MPM step (about 0.7 us here)
  EXPECT_EQ(handoffs[0]["trigger"]["trigger"], "burn_complete");
  EXPECT_GT(handoffs[0]["tracers"].get<int>(), 2000);
  const auto out = scene.parent_path() / "out";
  EXPECT_TRUE(std::filesystem::exists(out / "gauges.csv"));
  // Outputs at 0 (the MPM's), 10, 20, 30 us (the FDM's), each listed with its files.
  const auto& outputs = summary["details"]["afdmp"]["outputs"];
  ASSERT_EQ(outputs.size(), 4u);
  EXPECT_EQ(outputs[0]["solver"], "mpm");
  EXPECT_EQ(outputs[3]["solver"], "fdm");
  for (const auto& output : outputs) {
    ASSERT_FALSE(output["files"].empty());
    for (const auto& file : output["files"])
      EXPECT_TRUE(std::filesystem::exists(file.get<std::string>())) << file;
  }
}

TEST(AfdmpRun, The_chunk_size_of_a_handoff_does_not_change_the_result) {
  const auto scene = scene_variant("afdmp_blast_2d", "chunks", kV3Fast);
  const auto whole = run(scene, "whole");
  const auto chunked = run(scene, "chunked", 4096);
  const auto& a = whole["details"]["afdmp"]["handoffs"][0];
  const auto& b = chunked["details"]["afdmp"]["handoffs"][0];
  EXPECT_EQ(a["export"]["chunks"], 6);  // one per field
  EXPECT_GT(b["import"]["chunks"].get<int>(), 30);
  EXPECT_EQ(a["solver_totals"], b["solver_totals"]);
  EXPECT_EQ(read_text(scene.parent_path() / "whole" / "gauges.csv"),
            read_text(scene.parent_path() / "chunked" / "gauges.csv"));
}

TEST(AfdmpRun, A_spherical_charge_detonates_in_1D_and_is_remapped_conservatively) {
  const auto scene = scene_variant(
      "afdmp_free_air_3d_1d", "v4s",
      {{"cells: [100, 100, 100]", "cells: [20, 20, 20]"}, {"end: 3.4e-4", "end: 2.0e-5"}});
  const auto summary = run(scene, "out");
  EXPECT_THAT(phase_names(summary),
              ::testing::ElementsAre("spherical_detonation", "fdm_blast", "done"));
  const auto& handoff = summary["details"]["afdmp"]["handoffs"][0];
  EXPECT_EQ(handoff["name"], "spherical_to_fdm");
  expect_round_off(handoff);
  // The octant holds an eighth of the 1D stage's mass (the stage's ball lies in the grid).
  EXPECT_NEAR(handoff["received_inside_grid"]["mass"].get<double>(),
              handoff["stage_totals"]["mass"].get<double>() / 8, 1e-12);
  // The front reached handoff_radius = 40 mm.
  EXPECT_GE(handoff["trigger"]["value"].get<double>(), 0.04);
}

TEST(AfdmpRun, The_FSI_zone_wakes_as_particles_when_the_blast_reaches_it) {
  const auto scene = scene_variant(
      "afdmp_steel_plate_2d", "v5",
      {{"cells: [1000, 500, 1]", "cells: [100, 50, 1]"}, {"end: 3.0e-4", "end: 8.0e-5"}});
  const auto summary = run(scene, "out");
  EXPECT_THAT(phase_names(summary),
              ::testing::ElementsAre("mpm_detonation", "fdm_blast", "mpm_fsi", "done"));
  const auto& handoffs = summary["details"]["afdmp"]["handoffs"];
  ASSERT_EQ(handoffs.size(), 2u);
  EXPECT_EQ(handoffs[1]["name"], "fdm_to_mpm");
  for (const auto& h : handoffs) expect_round_off(h);
  const auto& trigger = handoffs[1]["trigger"];
  EXPECT_EQ(trigger["trigger"], "pressure");
  EXPECT_GT(trigger["value"].get<double>(), trigger["threshold"].get<double>());
  // 2^d = 4 particles per cell (T (3-18)) of the 80 x 50 fluid cells at least,
  // more in mixed cells where tracers become particles (T (3-19)).
  EXPECT_GE(handoffs[1]["particles"].get<int>(), 4 * 80 * 50);
  EXPECT_TRUE(handoffs[1].contains("fsi_face_leak"));
  const std::string header = read_text(scene.parent_path() / "out" / "gauges.csv").substr(0, 2000);
  EXPECT_THAT(header, HasSubstr("plate_centre.mises_stress[Pa]"));
}

TEST(AfdmpRun, Solver_processes_over_ipc_give_the_embedded_result) {
  const auto scene = scene_variant("afdmp_blast_2d", "processes", kV3Fast);
  const auto embedded = run(scene, "embedded");
  const auto processes = run(scene, "processes", std::uint64_t{64} << 20, LaunchMode::processes);
  EXPECT_EQ(processes["status"], "completed");
  EXPECT_EQ(embedded["details"]["afdmp"]["handoffs"][0]["solver_totals"],
            processes["details"]["afdmp"]["handoffs"][0]["solver_totals"]);
  EXPECT_EQ(read_text(scene.parent_path() / "embedded" / "gauges.csv"),
            read_text(scene.parent_path() / "processes" / "gauges.csv"));
}

// A recording holds the export streams (several replies to one request) and
// the imports; each solver replays it bit for bit (proto §10, §15).
TEST(AfdmpRun, A_recorded_run_replays_bit_for_bit_against_each_solver) {
  const auto scene = scene_variant(
      "afdmp_steel_plate_2d", "replay",
      {{"cells: [1000, 500, 1]", "cells: [100, 50, 1]"}, {"end: 3.0e-4", "end: 7.0e-5"}});
  const auto recording = scene.parent_path() / "run.mpfdrec";
  (void)run(scene, "out", std::uint64_t{1} << 16, LaunchMode::embedded, recording);
  for (const std::string solver : {"fdm", "mpm"}) {
    ReplayOptions options;
    options.solver = solver;
    options.out_dir = scene.parent_path() / ("replay-" + solver);
    const auto report = replay(recording, options, embedded_serve(solver));
    EXPECT_FALSE(report.divergence.has_value()) << solver << ": " << *report.divergence;
    EXPECT_GT(report.values_compared, 1000u) << solver;
  }
}

TEST(AfdmpRun, A_scene_the_coupler_cannot_drive_is_refused_before_anything_is_written) {
  const auto scene = scene_variant("afdmp_steel_plate_2d", "refused",
                                   {{"activation_pressure: 2.0e5", "activation_pressure: -1"}});
  const auto out = scene.parent_path() / "out";
  try {
    (void)run(scene, "out");
    FAIL() << "a negative activation pressure was accepted";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("activation_pressure"));
  }
  EXPECT_FALSE(std::filesystem::exists(out / "summary.json"));
}

}  // namespace
}  // namespace mpfd::coupler
