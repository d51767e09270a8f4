// Checkpoint and restart of a coupled CFDMP run (coupler/run/coupler_checkpoint.hpp)
// with the real solvers on threads: a run restarted from a checkpoint ends bit for
// bit as the run that was never stopped (gauges, audit, both solvers' last
// snapshots and the snapshot series), checkpointing does not change a run, and a
// restart that cannot be made is refused before anything in the folder changes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/core/error.hpp"
#include "common/io/hdf5_file.hpp"
#include "coupler/run/launch.hpp"

namespace mpfd::coupler {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string read_text(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// configs/<config>.yaml with `from` -> `to` edits, as <tag>/scene.yaml in a fresh folder.
fs::path scene_file(const std::string& config, const std::string& tag,
                    const std::vector<std::pair<std::string, std::string>>& edits) {
  std::string text = read_text(fs::path(MPFD_CONFIGS) / (config + ".yaml"));
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    if (at == std::string::npos) throw Error("test scene edit: '" + from + "' not in " + config);
    text.replace(at, from.size(), to);
  }
  const auto dir = fs::temp_directory_path() / ("mpfd-restart-test-" + tag);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.yaml") << text;
  return dir / "scene.yaml";
}

/// configs/cfdmp_blast_2d_coarse.yaml to 40 us, outputs every 10 us: the blast enters the
/// MPM zone before 20 us, so particles are injected on either side of a checkpoint there.
fs::path blast_scene(const std::string& tag,
                     std::vector<std::pair<std::string, std::string>> edits = {}) {
  edits.insert(edits.begin(), {"end: 6.0e-5", "end: 4.0e-5"});
  return scene_file("cfdmp_blast_2d_coarse", tag, edits);
}

struct RunArgs {
  int checkpoint_every = 0;
  bool restart = false;
  bool overwrite = true;
};

nlohmann::json run(const fs::path& scene, const fs::path& out, const RunArgs& args) {
  LaunchOptions launch;
  launch.mode = LaunchMode::embedded;
  launch.overwrite = args.overwrite;
  launch.restart = args.restart;
  CoupledRunOptions options;
  options.out_dir = out;
  options.progress = false;
  options.checkpoint_every = args.checkpoint_every;
  (void)launch_run(scene, launch, options, "coupler");
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

std::vector<double> dataset(const fs::path& file, const std::string& path) {
  return io::Hdf5File(file, io::Hdf5File::Mode::read).read_dataset(path).values;
}

/// Equal bit for bit, NaN where NaN (a gauge's MPM columns while nothing samples them).
void expect_same_values(const std::vector<double>& a, const std::vector<double>& b,
                        const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i])))) ++differ;
  EXPECT_EQ(differ, 0u) << what << ": " << differ << " of " << a.size() << " values differ";
}

/// The two runs' gauges, audit and last snapshots are the same.
/// `fdm_last`, `mpm_last`: each solver's last snapshot (a zone asleep writes none).
void expect_same_run(const fs::path& a, const fs::path& b, const std::string& fdm_last,
                     const std::string& mpm_last) {
  expect_same_values(dataset(a / "gauges.h5", "/time"), dataset(b / "gauges.h5", "/time"),
                     "gauge times");
  for (const char* gauge : {"p1_fdm", "p2_mpm"})
    for (const char* q : {"pressure", "density", "velocity_x", "position_x"}) {
      const std::string path = std::string("/gauges/") + gauge + "/" + q;
      expect_same_values(dataset(a / "gauges.h5", path), dataset(b / "gauges.h5", path), path);
    }
  EXPECT_EQ(read_text(a / "gauges.csv"), read_text(b / "gauges.csv"));
  const auto summary = [](const fs::path& dir) {
    std::ifstream in(dir / "summary.json");
    return nlohmann::json::parse(in);
  };
  const auto sa = summary(a), sb = summary(b);
  EXPECT_EQ(sa["conservation"], sb["conservation"]);
  EXPECT_EQ(sa["details"]["zones"], sb["details"]["zones"]);
  EXPECT_EQ(sa["details"]["crossing"], sb["details"]["crossing"]);
  EXPECT_EQ(sa["details"]["activation"], sb["details"]["activation"]);
  EXPECT_EQ(sa["steps"], sb["steps"]);
  const fs::path fdm = fs::path("fdm") / "snapshots" / fdm_last;
  const fs::path mpm = fs::path("mpm") / "snapshots" / mpm_last;
  expect_same_values(dataset(a / fdm, "/cells/pressure"), dataset(b / fdm, "/cells/pressure"),
                     "fdm pressure");
  expect_same_values(dataset(a / mpm, "/particles/position"),
                     dataset(b / mpm, "/particles/position"), "mpm positions");
  // The series goes on: every earlier output is listed, none from 0 again.
  EXPECT_EQ(read_text(a / "fdm" / "cells.xmf"), read_text(b / "fdm" / "cells.xmf"));
  EXPECT_EQ(read_text(a / "mpm" / "particles.xmf"), read_text(b / "mpm" / "particles.xmf"));
}

/// A copy of run `from` whose newest checkpoint is the one of `step`; later ones removed.
fs::path copy_back_to(const fs::path& from, const fs::path& to, std::int64_t step) {
  fs::remove_all(to);
  fs::copy(from, to, fs::copy_options::recursive);
  for (const auto& entry : fs::directory_iterator(to / "checkpoints")) {
    const std::string name = entry.path().filename().string();
    if (name > coupler_checkpoint_file(to, step).filename().string()) fs::remove(entry.path());
  }
  return to;
}

std::int64_t checkpoint_step(const nlohmann::json& summary) {
  return summary["details"]["checkpoints"]["last"]["step"].get<std::int64_t>();
}

TEST(CoupledRestart, A_run_restarted_from_its_checkpoint_ends_as_the_run_never_stopped) {
  const auto scene = blast_scene("blast");
  const auto dir = scene.parent_path();
  const auto straight = run(scene, dir / "straight", {});
  const auto checkpointed = run(scene, dir / "checkpointed", {.checkpoint_every = 2});
  ASSERT_EQ(checkpointed["status"], "completed");
  // Outputs 1 ... 4 at 10 ... 40 us: checkpoints after outputs 2 (20 us); none at the end.
  EXPECT_EQ(checkpointed["details"]["checkpoints"]["last"]["time_s"].get<double>(), 2.0e-5);
  const std::int64_t step = checkpoint_step(checkpointed);
  EXPECT_TRUE(fs::exists(dir / "checkpointed" / "fdm" / "checkpoints"));
  EXPECT_TRUE(fs::exists(dir / "checkpointed" / "mpm" / "checkpoints"));
  // Checkpointing changes nothing in the run.
  expect_same_run(dir / "straight", dir / "checkpointed", "snapshot_000004.h5",
                  "snapshot_000004.h5");
  EXPECT_EQ(straight["conservation"], checkpointed["conservation"]);

  // The run stopped after its checkpoint: later outputs and the summary say so,
  // and the restart goes on from 20 us over them.
  const auto restarted = copy_back_to(dir / "checkpointed", dir / "restarted", step);
  const auto summary = run(scene, restarted, {.restart = true, .overwrite = false});
  ASSERT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["details"]["checkpoints"]["restarted_from"]["step"].get<std::int64_t>(), step);
  EXPECT_GT(summary["details"]["crossing"]["injected_particles"].get<int>(), 20000);
  expect_same_run(dir / "checkpointed", restarted, "snapshot_000004.h5", "snapshot_000004.h5");
}

TEST(CoupledRestart, Gas_leaving_the_mpm_zone_across_the_checkpoint_is_deposited_as_before) {
  // configs/cfdmp_sod_1d.yaml mirrored: the dense gas in the MPM zone, x > 0.8, so the
  // flow leaves the zone through its face at x = 0.6 (particles removed and deposited,
  // parcels returned). Checkpoints after outputs 3, 6, 9 (of 10); the restart from 3.
  const auto scene = scene_file(
      "cfdmp_sod_1d", "sod",
      {{"density: 1.0\n    pressure: 1.0\n    shape: {box: {lower: [0, 0, 0], upper: [0.5,",
        "density: 0.125\n    pressure: 0.1\n    shape: {box: {lower: [0, 0, 0], upper: [0.8,"},
       {"density: 0.125\n    pressure: 0.1\n    shape: {box: {lower: [0.5,",
        "density: 1.0\n    pressure: 1.0\n    shape: {box: {lower: [0.8,"},
       {"output:\n",
        "gauges:\n  - {name: p1_fdm, position: [0.305, 0.005, 0.005]}\n"
        "  - {name: p2_mpm, position: [0.705, 0.005, 0.005]}\noutput:\n"}});
  const auto dir = scene.parent_path();
  const auto checkpointed = run(scene, dir / "checkpointed", {.checkpoint_every = 3});
  ASSERT_EQ(checkpointed["status"], "completed");
  EXPECT_GT(checkpointed["details"]["crossing"]["removed_particles"].get<int>(), 10);
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir / "checkpointed" / "checkpoints"))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_EQ(files.size(), 3u);
  const auto step = static_cast<std::int64_t>(
      io::Hdf5File(files.front(), io::Hdf5File::Mode::read).read_attribute("/", "step"));
  const auto restarted = copy_back_to(dir / "checkpointed", dir / "restarted", step);
  const auto summary = run(scene, restarted, {.restart = true, .overwrite = false});
  ASSERT_EQ(summary["status"], "completed");
  expect_same_run(dir / "checkpointed", restarted, "snapshot_000010.h5", "snapshot_000010.h5");
}

TEST(CoupledRestart, A_zone_asleep_at_the_checkpoint_wakes_after_the_restart_as_it_would_have) {
  // The MPM zone sleeps until the blast's 1 MPa reaches the strip cells: in the step to
  // the first output (10 us), so the first checkpoint holds a zone whose watch has fired
  // and that wakes at the start of the next step.
  const auto scene = blast_scene(
      "dormant",
      {{"mpm: {lower: [0.11, 0, 0], upper: [0.16, 0.5, 0.005]}",
        "mpm: {lower: [0.11, 0, 0], upper: [0.16, 0.5, 0.005], activation_pressure: 1.0e6}"}});
  const auto dir = scene.parent_path();
  const auto checkpointed = run(scene, dir / "checkpointed", {.checkpoint_every = 1});
  ASSERT_EQ(checkpointed["status"], "completed");
  const double woke = checkpointed["details"]["activation"]["time_s"].get<double>();
  ASSERT_EQ(woke, 1.0e-5);
  // The first checkpoint (10 us) names no MPM file: the sleeping zone is its Setup's state.
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir / "checkpointed" / "checkpoints"))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 2u);
  const io::Hdf5File oldest(files.front(), io::Hdf5File::Mode::read);
  EXPECT_EQ(oldest.read_string_attribute("/", "mpm_path"), "");
  EXPECT_EQ(oldest.read_attribute("/", "time"), 1.0e-5);
  EXPECT_EQ(oldest.read_attribute("/activation", "dormant"), 1.0);
  EXPECT_GT(oldest.read_attribute("/activation", "trigger_time"), 0.0);  // fired: not NaN
  const auto step = static_cast<std::int64_t>(oldest.read_attribute("/", "step"));

  const auto restarted = copy_back_to(dir / "checkpointed", dir / "restarted", step);
  const auto summary = run(scene, restarted, {.restart = true, .overwrite = false});
  ASSERT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["details"]["activation"]["time_s"].get<double>(), woke);
  // The MPM's series starts at its first output awake (20 us): 3 snapshots.
  expect_same_run(dir / "checkpointed", restarted, "snapshot_000004.h5", "snapshot_000002.h5");
}

TEST(CoupledRestart, A_restart_that_cannot_be_made_is_refused_and_the_folder_is_unchanged) {
  const auto scene = blast_scene("refused");
  const auto dir = scene.parent_path();
  run(scene, dir / "plain", {});
  const std::string summary = read_text(dir / "plain" / "summary.json");
  const std::string gauges = read_text(dir / "plain" / "gauges.csv");
  const auto refused = [&](const fs::path& scene_path, const fs::path& out, RunArgs args) {
    try {
      run(scene_path, out, args);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_THAT(refused(scene, dir / "plain", {.restart = true, .overwrite = false}),
              HasSubstr("holds no coupler_NNNNNN.h5; run with --checkpoint-every K"));
  EXPECT_THAT(refused(scene, dir / "plain", {.restart = true, .overwrite = true}),
              HasSubstr("give one of the two"));
  EXPECT_EQ(read_text(dir / "plain" / "summary.json"), summary);
  EXPECT_EQ(read_text(dir / "plain" / "gauges.csv"), gauges);

  // A checkpointed run, restarted with another scene text (a changed CFL).
  run(scene, dir / "checkpointed", {.checkpoint_every = 1});
  const std::string finished = read_text(dir / "checkpointed" / "summary.json");
  const auto changed = blast_scene("refused-changed", {{"cfl: 0.3", "cfl: 0.25"}});
  EXPECT_THAT(refused(changed, dir / "checkpointed", {.restart = true, .overwrite = false}),
              HasSubstr("was written for another scene text (attribute scene_sha256)"));
  EXPECT_EQ(read_text(dir / "checkpointed" / "summary.json"), finished);

  const auto afdmp_scene = fs::path(MPFD_CONFIGS) / "afdmp_blast_2d.yaml";
  EXPECT_THAT(refused(afdmp_scene, dir / "afdmp", {.checkpoint_every = 1}),
              HasSubstr("has solver.method afdmp"));
  EXPECT_FALSE(fs::exists(dir / "afdmp"));
}

}  // namespace
}  // namespace mpfd::coupler
