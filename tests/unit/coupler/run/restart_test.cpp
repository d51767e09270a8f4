// Checkpoint and restart of coupled CFDMP and AFDMP runs
// (coupler/run/coupler_checkpoint.hpp) with the real solvers on threads: a run
// restarted from a checkpoint ends bit for bit as the run that was never stopped
// (gauges, audit, handoffs, every snapshot and the snapshot series),
// checkpointing does not change a run, and a restart that cannot be made is
// refused before anything in the folder changes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
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
  int checkpoint_keep = 0;  // all: restart_from_each restarts from every one
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
  options.checkpoint_keep = args.checkpoint_keep;
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

/// The snapshot files of <dir>/<solver>/snapshots, by name.
std::vector<std::string> snapshots(const fs::path& dir, const std::string& solver) {
  std::vector<std::string> names;
  const fs::path folder = dir / solver / "snapshots";
  if (fs::is_directory(folder))
    for (const auto& entry : fs::directory_iterator(folder))
      names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

/// The two runs' gauges, audit, snapshots and snapshot series are the same.
void expect_same_run(const fs::path& a, const fs::path& b) {
  expect_same_values(dataset(a / "gauges.h5", "/time"), dataset(b / "gauges.h5", "/time"),
                     "gauge times");
  const auto scene_gauges =
      nlohmann::json::parse(read_text(a / "summary.json"))["details"]["gauges"];
  ASSERT_FALSE(scene_gauges.empty());
  for (const auto& gauge : scene_gauges)
    for (const char* q : {"pressure", "density", "velocity_x", "position_x"}) {
      const std::string path = "/gauges/" + gauge["name"].get<std::string>() + "/" + q;
      expect_same_values(dataset(a / "gauges.h5", path), dataset(b / "gauges.h5", path), path);
    }
  EXPECT_EQ(read_text(a / "gauges.csv"), read_text(b / "gauges.csv"));
  const auto sa = nlohmann::json::parse(read_text(a / "summary.json"));
  const auto sb = nlohmann::json::parse(read_text(b / "summary.json"));
  EXPECT_EQ(sa["conservation"], sb["conservation"]);
  EXPECT_EQ(sa["steps"], sb["steps"]);
  for (const char* detail : {"zones", "crossing", "activation", "steps_limited_by"})  // CFDMP's
    EXPECT_EQ(sa["details"].value(detail, nlohmann::json()),
              sb["details"].value(detail, nlohmann::json()))
        << detail;
  if (sa["details"].contains("afdmp")) {  // the records but for their wall times
    for (const char* records : {"handoffs", "phases"}) {
      auto ra = sa["details"]["afdmp"][records], rb = sb["details"]["afdmp"][records];
      for (auto* list : {&ra, &rb})
        for (auto& record : *list) record.erase("wall_s");
      EXPECT_EQ(ra, rb) << records;
    }
    EXPECT_EQ(sa["details"]["afdmp"]["transitions"], sb["details"]["afdmp"]["transitions"]);
    EXPECT_EQ(sa["details"]["afdmp"]["audit"], sb["details"]["afdmp"]["audit"]);
  }
  for (const auto& [solver, field] :
       {std::pair{"fdm", "/cells/pressure"}, std::pair{"mpm", "/particles/position"}}) {
    const auto names = snapshots(a, solver);
    ASSERT_EQ(names, snapshots(b, solver)) << solver;
    for (const auto& name : names) {
      const fs::path file = fs::path(solver) / "snapshots" / name;
      expect_same_values(dataset(a / file, field), dataset(b / file, field), file.string());
    }
  }
  // The series goes on: every earlier output is listed, none from 0 again.
  for (const char* series : {"fdm/cells.xmf", "mpm/particles.xmf"})
    EXPECT_EQ(read_text(a / series), read_text(b / series)) << series;
}

/// Copies `groups` of HDF5 file `from` into `to` (HDF5's own H5Ocopy).
void copy_groups(const fs::path& from, const fs::path& to, const std::vector<std::string>& groups) {
  const hid_t source = H5Fopen(from.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t target = H5Fopen(to.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  ASSERT_GE(source, 0);
  ASSERT_GE(target, 0);
  for (const auto& group : groups)
    EXPECT_GE(H5Ocopy(source, group.c_str(), target, group.c_str(), H5P_DEFAULT, H5P_DEFAULT), 0)
        << group;
  H5Fclose(target);
  H5Fclose(source);
}

/// Every coupler checkpoint of the run in `out`, oldest first.
std::vector<fs::path> checkpoints_of(const fs::path& out) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(out / "checkpoints"))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// A copy of the finished run `from` as a run stopped after its checkpoint `checkpoint`:
/// later checkpoints (the coupler's and the solvers') and snapshots gone, the summary
/// of a run still going, and a last gauges.csv row that the checkpoint does not hold.
fs::path stopped_after(const fs::path& from, const fs::path& checkpoint, const fs::path& to) {
  fs::remove_all(to);
  fs::copy(from, to, fs::copy_options::recursive);
  const io::Hdf5File header(checkpoint, io::Hdf5File::Mode::read);
  const double time = header.read_attribute("/", "time");
  for (const auto& file : checkpoints_of(to))
    if (file.filename() > checkpoint.filename()) fs::remove(file);
  for (const char* solver : {"fdm", "mpm"}) {
    // coupled_NNNNNN.h5[.sha256] of later coupled steps
    const fs::path solver_checkpoints = to / solver / "checkpoints";
    if (fs::is_directory(solver_checkpoints))
      for (const auto& entry : fs::directory_iterator(solver_checkpoints))
        if (std::stod(entry.path().filename().string().substr(8, 6)) >
            header.read_attribute("/", "step"))
          fs::remove(entry.path());
    for (const auto& name : snapshots(to, solver)) {
      const fs::path file = to / solver / "snapshots" / name;
      // A solver's clock may lie an ulp or two off the coupler's: after, not at, the checkpoint.
      if (io::Hdf5File(file, io::Hdf5File::Mode::read).read_attribute("/", "time") >
          time * (1 + 1e-9))
        fs::remove(file);
    }
  }
  std::ofstream(to / "gauges.csv", std::ios::app) << "1.0,not,a,sample\n";
  std::ofstream(to / "summary.json") << R"({"status": "running"})";
  return to;
}

/// Restarts the run in <dir>/checkpointed, stopped after each of its checkpoints in
/// turn, and expects each restart to end as the run that was never stopped.
void restart_from_each(const fs::path& scene) {
  const auto dir = scene.parent_path();
  for (const auto& checkpoint : checkpoints_of(dir / "checkpointed")) {
    SCOPED_TRACE("restarted from " + checkpoint.filename().string());
    const auto restarted = stopped_after(dir / "checkpointed", checkpoint, dir / "restarted");
    const auto summary = run(scene, restarted, {.restart = true, .overwrite = false});
    EXPECT_EQ(summary["status"], "completed");
    EXPECT_EQ(summary["details"]["checkpoints"]["restarted_from"]["file"],
              (restarted / "checkpoints" / checkpoint.filename()).string());
    expect_same_run(dir / "checkpointed", restarted);
  }
}

TEST(CoupledRestart, A_run_restarted_from_its_checkpoint_ends_as_the_run_never_stopped) {
  const auto scene = blast_scene("blast");
  const auto dir = scene.parent_path();
  const auto straight = run(scene, dir / "straight", {});
  const auto checkpointed = run(scene, dir / "checkpointed", {.checkpoint_every = 2});
  ASSERT_EQ(checkpointed["status"], "completed");
  // Outputs 1 ... 4 at 10 ... 40 us: a checkpoint after output 2 (20 us), none at the end.
  const auto files = checkpoints_of(dir / "checkpointed");
  ASSERT_EQ(files.size(), 1u);
  const io::Hdf5File header(files[0], io::Hdf5File::Mode::read);
  EXPECT_EQ(header.read_attribute("/", "time"), 2.0e-5);
  EXPECT_EQ(checkpointed["details"]["checkpoints"]["last"]["file"], files[0].string());
  EXPECT_TRUE(fs::exists(dir / "checkpointed" / "fdm" / "checkpoints"));
  EXPECT_TRUE(fs::exists(dir / "checkpointed" / "mpm" / "checkpoints"));
  // Checkpointing changes nothing in the run.
  expect_same_run(dir / "straight", dir / "checkpointed");

  restart_from_each(scene);
  // Particles were injected on both sides of the checkpoint.
  const double before = header.read_attribute("/loop", "injected_particles");
  EXPECT_GT(before, 0.0);
  EXPECT_GT(checkpointed["details"]["crossing"]["injected_particles"].get<double>(), before);
}

TEST(CoupledRestart, Gas_leaving_the_mpm_zone_across_the_checkpoint_is_deposited_as_before) {
  // configs/cfdmp_sod_1d.yaml mirrored: the dense gas in the MPM zone, x > 0.8, so the
  // flow leaves the zone through its face at x = 0.6 (particles removed and deposited,
  // parcels returned). Checkpoints after outputs 3, 6, 9 (of 10).
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
  ASSERT_EQ(checkpoints_of(dir / "checkpointed").size(), 3u);
  // The rarefaction reaches the face (0.2 m at c = 1.18 m/s) after the first checkpoint
  // (0.06 s): particles are removed on both sides of the last two (0.12 and 0.18 s).
  const double removed = checkpointed["details"]["crossing"]["removed_particles"].get<double>();
  const io::Hdf5File second(checkpoints_of(dir / "checkpointed")[1], io::Hdf5File::Mode::read);
  const io::Hdf5File third(checkpoints_of(dir / "checkpointed")[2], io::Hdf5File::Mode::read);
  EXPECT_GT(second.read_attribute("/loop", "removed_particles"), 0.0);
  EXPECT_GT(removed, third.read_attribute("/loop", "removed_particles"));
  // The face-drain watch's last two deposits (face cell, share, density, taken back, particles).
  EXPECT_EQ(third.read_dataset("/step/face_drain_last").values.size(), 5u);
  EXPECT_EQ(third.read_dataset("/step/face_drain_previous").values.size(), 5u);
  restart_from_each(scene);

  // --out given relative to the working folder: the solvers' files are found again.
  const fs::path relative = fs::relative(dir / "relative", fs::current_path());
  ASSERT_TRUE(relative.is_relative());
  run(scene, relative, {.checkpoint_every = 3});
  const auto files = checkpoints_of(relative);
  const io::Hdf5File header(files.back(), io::Hdf5File::Mode::read);
  char expected[64];
  std::snprintf(expected, sizeof expected, "fdm/checkpoints/coupled_%06d.h5",
                static_cast<int>(header.read_attribute("/", "step")));     // the coupled step
  EXPECT_EQ(header.read_string_attribute("/", "fdm_path"), expected);      // relative to the run
  std::ofstream(relative / "summary.json") << R"({"status": "running"})";  // as if stopped
  const auto summary = run(scene, relative, {.restart = true, .overwrite = false});
  EXPECT_EQ(summary["status"], "completed");
  expect_same_run(dir / "checkpointed", relative);
}

TEST(CoupledRestart, A_zone_asleep_at_the_checkpoint_wakes_after_the_restart_as_it_would_have) {
  // The MPM zone sleeps until the blast's 1 MPa reaches the strip cells: in the step to
  // the first output (10 us), so the first checkpoint holds a zone whose watch has fired
  // and that wakes at the start of the next step; the later ones, a zone awake.
  const auto scene = blast_scene(
      "dormant",
      {{"mpm: {lower: [0.11, 0, 0], upper: [0.16, 0.5, 0.005]}",
        "mpm: {lower: [0.11, 0, 0], upper: [0.16, 0.5, 0.005], activation_pressure: 1.0e6}"}});
  const auto dir = scene.parent_path();
  const auto checkpointed = run(scene, dir / "checkpointed", {.checkpoint_every = 1});
  ASSERT_EQ(checkpointed["status"], "completed");
  ASSERT_EQ(checkpointed["details"]["activation"]["time_s"].get<double>(), 1.0e-5);
  const auto files = checkpoints_of(dir / "checkpointed");
  ASSERT_EQ(files.size(), 3u);
  // The first names no MPM file: the sleeping zone is its Setup's state.
  const io::Hdf5File oldest(files.front(), io::Hdf5File::Mode::read);
  EXPECT_EQ(oldest.read_string_attribute("/", "mpm_path"), "");
  EXPECT_EQ(oldest.read_attribute("/", "time"), 1.0e-5);
  EXPECT_EQ(oldest.read_attribute("/activation", "dormant"), 1.0);
  EXPECT_GT(oldest.read_attribute("/activation", "trigger_time"), 0.0);  // fired: not NaN
  const io::Hdf5File second(files[1], io::Hdf5File::Mode::read);
  EXPECT_NE(second.read_string_attribute("/", "mpm_path"), "");
  restart_from_each(scene);
}

/// The AFDMP phase of each checkpoint of the run in <dir>/checkpointed (afdmp_phase.hpp:
/// 0 mpm_detonation, 1 spherical_detonation, 2 fdm_blast, 3 mpm_fsi) and which solvers'
/// checkpoints it names.
struct AfdmpCheckpoint {
  int phase;
  bool fdm, mpm;
  bool operator==(const AfdmpCheckpoint&) const = default;
};

std::vector<AfdmpCheckpoint> afdmp_checkpoints(const fs::path& scene) {
  std::vector<AfdmpCheckpoint> seen;
  for (const auto& file : checkpoints_of(scene.parent_path() / "checkpointed")) {
    const io::Hdf5File h5(file, io::Hdf5File::Mode::read);
    seen.push_back({static_cast<int>(h5.read_attribute("/phases", "phase")),
                    !h5.read_string_attribute("/", "fdm_path").empty(),
                    !h5.read_string_attribute("/", "mpm_path").empty()});
  }
  return seen;
}

TEST(CoupledRestart, An_afdmp_run_restarts_in_each_of_its_phases_and_hands_over_as_before) {
  // V5 coarse, as afdmp_run_test: MPM detonation (to 8.7 us), FDM blast, then the plate's
  // FSI phase (from 61 us); outputs every 5 us, a checkpoint after each but the last.
  const auto scene = scene_file("afdmp_steel_plate_2d", "v5",
                                {{"cells: [1000, 500, 1]", "cells: [100, 50, 1]"},
                                 {"end: 3.0e-4", "end: 7.0e-5"},
                                 {"interval: 2.0e-5", "interval: 5.0e-6"}});
  const auto checkpointed =
      run(scene, scene.parent_path() / "checkpointed", {.checkpoint_every = 1});
  ASSERT_EQ(checkpointed["status"], "completed");
  ASSERT_EQ(checkpointed["details"]["afdmp"]["handoffs"].size(), 2u);
  const auto seen = afdmp_checkpoints(scene);
  restart_from_each(scene);
  // The detonation: the MPM holds everything, the FDM only its Setup's state (no file).
  EXPECT_THAT(seen, ::testing::Contains(AfdmpCheckpoint{0, false, true}));
  // The FDM phase (the MPM holds the plate, idle) and the FSI phase (the FDM retired).
  EXPECT_THAT(seen, ::testing::Contains(AfdmpCheckpoint{2, true, true}));
  EXPECT_THAT(seen, ::testing::Contains(AfdmpCheckpoint{3, false, true}));
}

/// The solver checkpoint files in <out>/<solver>/checkpoints (no .sha256), as absolute paths.
std::set<fs::path> solver_checkpoint_files(const fs::path& out) {
  std::set<fs::path> files;
  for (const char* solver : {"fdm", "mpm"})
    if (fs::is_directory(out / solver / "checkpoints"))
      for (const auto& entry : fs::directory_iterator(out / solver / "checkpoints"))
        if (entry.path().extension() == ".h5")
          files.insert(fs::absolute(entry.path()).lexically_normal());
  return files;
}

TEST(CoupledRestart, Only_the_newest_checkpoints_are_kept_with_the_solver_files_they_name) {
  // V5 coarse: the MPM holds the plate idle through the FDM phase, then carries the FSI
  // phase; each coupler checkpoint has its own solver files.
  const auto scene = scene_file("afdmp_steel_plate_2d", "v5keep",
                                {{"cells: [1000, 500, 1]", "cells: [100, 50, 1]"},
                                 {"end: 3.0e-4", "end: 7.0e-5"},
                                 {"interval: 2.0e-5", "interval: 5.0e-6"}});
  const auto dir = scene.parent_path();
  run(scene, dir / "checkpointed", {.checkpoint_every = 1});
  const std::size_t all = checkpoints_of(dir / "checkpointed").size();
  const auto kept = run(scene, dir / "kept", {.checkpoint_every = 1, .checkpoint_keep = 2});
  const auto files = checkpoints_of(dir / "kept");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(kept["details"]["checkpoints"]["removed"], all - 2);
  std::set<fs::path> named;
  for (const auto& file : files) {
    const io::Hdf5File header(file, io::Hdf5File::Mode::read);
    for (const char* solver : {"fdm", "mpm"})
      if (const std::string path = header.read_string_attribute("/", std::string(solver) + "_path");
          !path.empty())
        named.insert(fs::absolute(dir / "kept" / path).lexically_normal());
  }
  EXPECT_EQ(solver_checkpoint_files(dir / "kept"), named);
  for (const auto& file : named) EXPECT_TRUE(fs::exists(file.string() + ".sha256")) << file;
  // The two kept: the last of the FDM phase (the FDM's and the idle MPM's) and the FSI phase's.
  EXPECT_EQ(named.size(), 3u);
  // A restart from the older one (the FDM phase's), taking checkpoints again and keeping
  // one, ends as the run that kept them all; its FSI-phase checkpoint replaces the stopped
  // run's, whose solver files go with it.
  const auto restarted = stopped_after(dir / "kept", files.front(), dir / "restarted");
  const auto summary =
      run(scene, restarted,
          {.checkpoint_every = 1, .checkpoint_keep = 1, .restart = true, .overwrite = false});
  EXPECT_EQ(summary["status"], "completed");
  expect_same_run(dir / "checkpointed", restarted);
  const auto left = checkpoints_of(restarted);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].filename(), files.back().filename());
  const io::Hdf5File last(left[0], io::Hdf5File::Mode::read);
  EXPECT_EQ(solver_checkpoint_files(restarted),
            std::set<fs::path>{fs::absolute(restarted / last.read_string_attribute("/", "mpm_path"))
                                   .lexically_normal()});
}

TEST(CoupledRestart, An_afdmp_run_from_a_1d_start_restarts_in_its_1d_stage_and_fdm_phase) {
  // V4 1D start, as afdmp_run_test, outputs every 2 us: the 1D stage (in the coupler,
  // handed over at 7.1 us) keeps its particles in the coupler's file and no solver has
  // one (the MPM retired, no FSI zone; the FDM as Setup made it); then the FDM phase.
  const auto scene = scene_file("afdmp_free_air_3d_1d", "v4s",
                                {{"cells: [100, 100, 100]", "cells: [20, 20, 20]"},
                                 {"end: 3.4e-4", "end: 1.2e-5"},
                                 {"interval: 5.0e-5", "interval: 2.0e-6"}});
  const auto checkpointed =
      run(scene, scene.parent_path() / "checkpointed", {.checkpoint_every = 1});
  ASSERT_EQ(checkpointed["status"], "completed");
  const auto seen = afdmp_checkpoints(scene);
  restart_from_each(scene);
  EXPECT_THAT(seen, ::testing::Contains(AfdmpCheckpoint{1, false, false}));
  EXPECT_THAT(seen, ::testing::Contains(AfdmpCheckpoint{2, true, false}));
  EXPECT_THAT(seen, ::testing::Each(::testing::Field(&AfdmpCheckpoint::mpm, false)));
  // A 1D stage file whose particles were seeded otherwise is refused, naming the entry.
  const auto files = checkpoints_of(scene.parent_path() / "checkpointed");
  const auto stopped = stopped_after(scene.parent_path() / "checkpointed", files.front(),
                                     scene.parent_path() / "tampered");
  {
    // Rewritten whole: HDF5 1.10 cannot modify this compact attribute in place.
    const hid_t file = H5Fopen(checkpoints_of(stopped).back().c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(file, 0);
    const hid_t stage = H5Gopen2(file, "/stage", H5P_DEFAULT);
    EXPECT_GE(H5Adelete(stage, "particles"), 0);
    const hid_t scalar = H5Screate(H5S_SCALAR);
    const hid_t count =
        H5Acreate2(stage, "particles", H5T_NATIVE_DOUBLE, scalar, H5P_DEFAULT, H5P_DEFAULT);
    const double three = 3;
    EXPECT_GE(H5Awrite(count, H5T_NATIVE_DOUBLE, &three), 0);
    H5Aclose(count);
    H5Sclose(scalar);
    H5Gclose(stage);
    H5Fclose(file);
  }
  // The refusal shuts down both solvers it started, the MPM too, which the stopped run had
  // retired: a liveness check (left waiting, an embedded solver ends only at its 60 s idle
  // timeout; the refusal itself takes under a second).
  const auto start = std::chrono::steady_clock::now();
  try {
    run(scene, stopped, {.restart = true, .overwrite = false});
    ADD_FAILURE() << "a tampered 1D stage was restarted";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), HasSubstr("holds 3 1D particles (/stage, attribute particles)"));
  }
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
}

TEST(CoupledRestart, A_restarts_solver_logs_keep_the_stopped_runs_and_an_earlier_restarts) {
  const auto dir = fs::temp_directory_path() / "mpfd-restart-test-logs";
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_EQ(solver_log_file(dir, "fdm_solver", std::nullopt), dir / "fdm_solver.log");
  std::ofstream(dir / "fdm_solver.log") << "the stopped run's\n";
  EXPECT_EQ(solver_log_file(dir, "fdm_solver", 382), dir / "fdm_solver_restart_382.log");
  std::ofstream(dir / "fdm_solver_restart_382.log") << "the first restart's\n";
  EXPECT_EQ(solver_log_file(dir, "fdm_solver", 382), dir / "fdm_solver_restart_382_2.log");
  std::ofstream(dir / "fdm_solver_restart_382_2.log") << "the second restart's\n";
  EXPECT_EQ(solver_log_file(dir, "fdm_solver", 382), dir / "fdm_solver_restart_382_3.log");
  EXPECT_EQ(solver_log_file(dir, "mpm_solver", 382), dir / "mpm_solver_restart_382.log");
  fs::remove_all(dir);
}

TEST(CoupledRestart, A_restart_that_cannot_be_made_is_refused_and_the_folder_is_unchanged) {
  const auto scene = blast_scene("refused");
  const auto dir = scene.parent_path();
  run(scene, dir / "plain", {});
  std::ofstream(dir / "plain" / "summary.json") << R"({"status": "running"})";  // as if stopped
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

  // A run that completed: nothing to go on with.
  run(scene, dir / "checkpointed", {.checkpoint_every = 1});
  const std::string finished = read_text(dir / "checkpointed" / "summary.json");
  EXPECT_THAT(refused(scene, dir / "checkpointed", {.restart = true, .overwrite = false}),
              HasSubstr("has completed (summary.json: status completed)"));
  EXPECT_EQ(read_text(dir / "checkpointed" / "summary.json"), finished);

  // A stopped run restarted with another scene text (a changed CFL).
  const auto files = checkpoints_of(dir / "checkpointed");
  const auto stopped = stopped_after(dir / "checkpointed", files.front(), dir / "stopped");
  const std::string stopped_summary = read_text(stopped / "summary.json");
  const auto changed = blast_scene("refused-changed", {{"cfl: 0.3", "cfl: 0.25"}});
  EXPECT_THAT(refused(changed, stopped, {.restart = true, .overwrite = false}),
              HasSubstr("was written for another scene text (attribute scene_sha256)"));
  EXPECT_EQ(read_text(stopped / "summary.json"), stopped_summary);

  // Coupler files the restart reads and refuses, before any solver restores and before
  // gauges.csv is rewritten: what the stopped run wrote stays as it was.
  const auto refused_in_place = [&](const fs::path& folder, const std::string& why) {
    const std::vector<fs::path> kept_files = {"gauges.csv", "gauges.h5", "fdm/cells.xmf",
                                              "mpm/particles.xmf"};
    std::vector<std::string> before;
    for (const auto& file : kept_files) before.push_back(read_text(folder / file));
    const auto fdm_snapshots = snapshots(folder, "fdm");
    EXPECT_THAT(refused(scene, folder, {.restart = true, .overwrite = false}), HasSubstr(why));
    for (std::size_t i = 0; i < kept_files.size(); ++i)
      EXPECT_EQ(read_text(folder / kept_files[i]), before[i]) << kept_files[i];
    EXPECT_EQ(snapshots(folder, "fdm"), fdm_snapshots);
    EXPECT_THAT(read_text(folder / "summary.json"), HasSubstr(why));  // why the restart failed
  };
  // Its header alone.
  const auto broken = stopped_after(dir / "checkpointed", files.front(), dir / "broken");
  const auto header = newest_checkpoint(broken, read_text(scene), 2);
  fs::remove(header.file);
  {
    io::Hdf5File header_only(header.file, io::Hdf5File::Mode::create);
    write_checkpoint_header(header_only, header, read_text(scene), 2);
  }
  refused_in_place(broken, "has no array '/loop/initial'");
  // Its state whole, but naming no file of one solver (`solver` in "fdm", "mpm").
  const auto without = [&](const std::string& solver) {
    const auto folder = stopped_after(dir / "checkpointed", files.front(), dir / ("no_" + solver));
    auto named = newest_checkpoint(folder, read_text(scene), 2);
    const fs::path original = named.file.string() + ".original";
    fs::rename(named.file, original);
    (solver == "fdm" ? named.fdm : named.mpm).reset();
    {
      io::Hdf5File rewritten(named.file, io::Hdf5File::Mode::create);
      write_checkpoint_header(rewritten, named, read_text(scene), 2);
    }
    copy_groups(original, named.file, {"/loop", "/step", "/gauges", "/activation"});
    fs::remove(original);
    return folder;
  };
  refused_in_place(without("mpm"), "names no MPM checkpoint for an awake zone");
  refused_in_place(without("fdm"), "names no FDM checkpoint (attribute fdm_path)");
}

}  // namespace
}  // namespace mpfd::coupler
