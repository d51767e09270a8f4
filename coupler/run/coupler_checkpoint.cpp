#include "coupler/run/coupler_checkpoint.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <utility>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "common/io/output_directory.hpp"
#include "cosim/serving/sha256.hpp"

namespace mpfd::coupler {
namespace {

namespace fs = std::filesystem;

void write_solver(io::Hdf5File& file, const std::string& name,
                  const std::optional<SolverCheckpoint>& solver, const fs::path& out_dir) {
  file.write_attribute("/", name + "_path",
                       solver ? io::path_in_run(solver->path, out_dir) : std::string());
  file.write_attribute("/", name + "_step",
                       static_cast<std::int64_t>(solver ? solver->step : std::uint64_t{0}));
}

std::optional<SolverCheckpoint> read_solver(const io::Hdf5File& file, const std::string& name,
                                            const fs::path& out_dir) {
  std::string path = file.read_string_attribute("/", name + "_path");
  if (path.empty()) return std::nullopt;
  if (fs::path(path).is_relative()) path = (fs::absolute(out_dir) / path).string();
  return SolverCheckpoint{path,
                          static_cast<std::uint64_t>(file.read_attribute("/", name + "_step"))};
}

/// <out_dir>/checkpoints/coupler_NNNNNN.h5, by step, oldest first.
std::vector<fs::path> coupler_checkpoint_files(const fs::path& out_dir) {
  const fs::path folder = out_dir / "checkpoints";
  const std::regex pattern(R"(coupler_(\d+)\.h5)");
  std::vector<std::pair<long long, fs::path>> found;
  if (fs::is_directory(folder))
    for (const auto& entry : fs::directory_iterator(folder)) {
      std::smatch match;
      const std::string name = entry.path().filename().string();
      if (std::regex_match(name, match, pattern))
        found.emplace_back(std::stoll(match[1].str()), entry.path());
    }
  std::sort(found.begin(), found.end());
  std::vector<fs::path> files;
  for (auto& [step, path] : found) files.push_back(std::move(path));
  return files;
}

/// The solver checkpoints a coupler file names, as absolute paths.
std::vector<fs::path> solver_files_of(const fs::path& coupler_file, const fs::path& out_dir) {
  const io::Hdf5File file(coupler_file, io::Hdf5File::Mode::read);
  std::vector<fs::path> named;
  for (const char* solver : {"fdm", "mpm"})
    if (const auto checkpoint = read_solver(file, solver, out_dir))
      named.push_back(fs::absolute(checkpoint->path).lexically_normal());
  return named;
}

}  // namespace

CheckpointLog::CheckpointLog(int every, int keep, bool restarting)
    : every_(every),
      keep_(keep),
      summary_ready_(!restarting),
      summary_{{"every_outputs", every}, {"keep", keep}, {"removed", 0}} {}

bool CheckpointLog::due(int outputs, bool run_goes_on) const {
  return every_ > 0 && (outputs - 1) % every_ == 0 && run_goes_on;
}

void CheckpointLog::taken(const CouplerCheckpoint& checkpoint) {
  remember(checkpoint);
  removed_ += prune_checkpoints(checkpoint.file.parent_path().parent_path(), keep_);
  summary_["removed"] = removed_;
}

void CheckpointLog::remember(const CouplerCheckpoint& checkpoint) {
  summary_["last"] = {
      {"file", checkpoint.file.string()}, {"step", checkpoint.step}, {"time_s", checkpoint.time}};
}

void CheckpointLog::restarted(const CouplerCheckpoint& from) {
  remember(from);
  summary_["restarted_from"] = summary_["last"];
  earlier_wall_seconds_ = from.wall_seconds;
  summary_ready_ = true;
}

fs::path coupler_checkpoint_file(const fs::path& out_dir, std::int64_t step) {
  char name[40];
  std::snprintf(name, sizeof name, "coupler_%06lld.h5", static_cast<long long>(step));
  return out_dir / "checkpoints" / name;
}

void write_checkpoint_header(io::Hdf5File& file, const CouplerCheckpoint& checkpoint,
                             const std::string& scene_text, int dimension) {
  file.write_attribute("/", "format", std::string(kCouplerCheckpointFormat));
  file.write_attribute("/", "format_version", kCouplerCheckpointVersion);
  file.write_attribute("/", "scene_sha256", cosim::sha256_hex(scene_text));
  file.write_attribute("/", "dimension", std::int64_t{dimension});
  file.write_attribute("/", "step", checkpoint.step);
  file.write_attribute("/", "time", checkpoint.time);
  file.write_attribute("/", "outputs", std::int64_t{checkpoint.outputs});
  file.write_attribute("/", "wall_seconds", checkpoint.wall_seconds);
  const fs::path out_dir = checkpoint.file.parent_path().parent_path();  // <out>/checkpoints/
  write_solver(file, "fdm", checkpoint.fdm, out_dir);
  write_solver(file, "mpm", checkpoint.mpm, out_dir);
}

void remove_checkpoints(const fs::path& out_dir) {
  for (const fs::path& folder :
       {out_dir / "checkpoints", out_dir / "fdm" / "checkpoints", out_dir / "mpm" / "checkpoints"})
    fs::remove_all(folder);
}

CouplerCheckpoint newest_checkpoint(const fs::path& out_dir, const std::string& scene_text,
                                    int dimension) {
  const fs::path summary = out_dir / "summary.json";
  if (fs::exists(summary)) {
    std::ifstream in(summary);
    const auto parsed = nlohmann::json::parse(in, nullptr, false);  // unreadable: not completed
    if (parsed.is_object() && parsed.value("status", "") == "completed")
      throw Error("--restart: the run in '" + out_dir.string() +
                  "' has completed (summary.json: status completed); there is nothing to go on "
                  "with. To run it again, run without --restart, with --overwrite");
  }
  const auto files = coupler_checkpoint_files(out_dir);
  if (files.empty())
    throw Error("--restart: '" + (out_dir / "checkpoints").string() +
                "' holds no coupler_NNNNNN.h5; run with --checkpoint-every K to write them");
  const fs::path& newest = files.back();
  const io::Hdf5File file(newest, io::Hdf5File::Mode::read);
  const auto refuse = [&](const std::string& what) {
    throw Error("--restart: '" + newest.string() + "' " + what);
  };
  std::string format;
  try {
    format = file.read_string_attribute("/", "format");
  } catch (const std::exception&) {
    refuse("has no 'format' attribute; expected '" + std::string(kCouplerCheckpointFormat) + "'");
  }
  if (format != kCouplerCheckpointFormat)
    refuse("has format '" + format + "'; expected '" + kCouplerCheckpointFormat + "'");
  const double version = file.read_attribute("/", "format_version");
  if (version != static_cast<double>(kCouplerCheckpointVersion))
    refuse("has format_version " + std::to_string(version) + "; this coupler reads " +
           std::to_string(kCouplerCheckpointVersion));
  if (file.read_string_attribute("/", "scene_sha256") != cosim::sha256_hex(scene_text))
    refuse(
        "was written for another scene text (attribute scene_sha256); restart with the scene "
        "file of that run, unchanged");
  const auto file_dimension = static_cast<int>(file.read_attribute("/", "dimension"));
  if (file_dimension != dimension)
    refuse("holds a " + std::to_string(file_dimension) + "D run; this scene is " +
           std::to_string(dimension) + "D");
  CouplerCheckpoint checkpoint{.file = newest,
                               .step = static_cast<std::int64_t>(file.read_attribute("/", "step")),
                               .time = file.read_attribute("/", "time"),
                               .outputs = static_cast<int>(file.read_attribute("/", "outputs")),
                               .wall_seconds = file.read_attribute("/", "wall_seconds"),
                               .fdm = read_solver(file, "fdm", out_dir),
                               .mpm = read_solver(file, "mpm", out_dir)};
  return checkpoint;
}

void CouplerCheckpoint::read_state(const std::function<void(const RestartReader&)>& restore) const {
  const io::Hdf5File h5(file, io::Hdf5File::Mode::read);
  restore(RestartReader(h5));
}

CouplerCheckpoint take_checkpoint(cosim::Hub& hub, const RunPosition& at, double wall_seconds,
                                  const fs::path& out_dir, const std::vector<std::string>& peers,
                                  std::chrono::milliseconds timeout, const std::string& scene_text,
                                  int dimension, const std::function<void(RestartWriter&)>& save) {
  const auto start = std::chrono::steady_clock::now();
  CouplerCheckpoint taken{.file = coupler_checkpoint_file(out_dir, at.step),
                          .step = at.step,
                          .time = at.time,
                          .outputs = at.outputs,
                          .wall_seconds = wall_seconds};
  // All at once: each solver writes while the others do, and none waits idle meanwhile.
  // Named by the coupled step, in the solver's <output_dir>: each coupler checkpoint has
  // its own files (an idle solver's step does not move, and a handoff may change its
  // state without a step, so a name by its own step could overwrite a file an older
  // coupler checkpoint names).
  char name[48];
  std::snprintf(name, sizeof name, "checkpoints/coupled_%06lld.h5",
                static_cast<long long>(at.step));
  for (const auto& peer : peers) {
    cosim::Message message;
    message.header.mutable_checkpoint()->set_path(name);
    hub.send(peer, std::move(message));
  }
  for (const auto& peer : peers) {
    const auto reply = hub.receive_from(peer, timeout);
    if (!reply.header.has_checkpoint_written())
      throw Error("solver '" + peer + "' answered Checkpoint with '" +
                  std::string(cosim::body_name(reply.header)) + "'");
    const auto& written = reply.header.checkpoint_written();
    (peer == "fdm" ? taken.fdm : taken.mpm) = SolverCheckpoint{written.path(), written.step()};
  }
  fs::create_directories(taken.file.parent_path());
  io::write_path_atomically(taken.file, [&](const fs::path& partial) {
    io::Hdf5File file(partial, io::Hdf5File::Mode::create);
    write_checkpoint_header(file, taken, scene_text, dimension);
    RestartWriter out(file);
    save(out);
  });
  Logger("coupler").info(
      "checkpoint at step ", taken.step, ", t = ", taken.time, " s: ", taken.file.string(), " (",
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), " s)");
  return taken;
}

int prune_checkpoints(const fs::path& out_dir, int keep) {
  const Logger logger("coupler");
  // A file that cannot go must not stop the run: the checkpoint just taken is complete.
  const auto warn = [&](const fs::path& file, const std::string& why) {
    logger.warn("cannot remove old checkpoint file '", file.string(), "' (", why, "); it stays");
  };
  const auto files = coupler_checkpoint_files(out_dir);
  if (keep <= 0 || files.size() <= static_cast<std::size_t>(keep)) return 0;
  const auto oldest_kept = files.end() - keep;
  std::set<fs::path> kept;
  for (auto file = oldest_kept; file != files.end(); ++file) try {
      for (const auto& named : solver_files_of(*file, out_dir)) kept.insert(named);
    } catch (const std::exception& error) {
      warn(*file, std::string("its solver files are unreadable, so none go: ") + error.what());
      return 0;
    }
  const fs::path run = fs::absolute(out_dir).lexically_normal();
  int removed = 0;
  for (auto file = files.begin(); file != oldest_kept; ++file) {
    std::vector<fs::path> named;
    try {
      named = solver_files_of(*file, out_dir);
    } catch (const std::exception& error) {
      warn(*file, error.what());
      continue;
    }
    std::error_code failed;
    fs::remove(*file, failed);  // first: a coupler file never names a removed solver file
    if (failed) {
      warn(*file, failed.message());
      continue;
    }
    ++removed;
    for (const auto& solver_file : named) {
      const fs::path inside = solver_file.lexically_relative(run);
      if (kept.contains(solver_file) || inside.empty() || *inside.begin() == "..") continue;
      for (const fs::path& part : {solver_file, fs::path(solver_file.string() + ".sha256")})
        if (fs::remove(part, failed); failed) warn(part, failed.message());
    }
  }
  return removed;
}

void restore_solvers(cosim::Hub& hub, const CouplerCheckpoint& from,
                     std::chrono::milliseconds timeout) {
  const std::pair<const char*, const std::optional<SolverCheckpoint>*> solvers[] = {
      {"fdm", &from.fdm}, {"mpm", &from.mpm}};
  for (const auto& [peer, file] : solvers) {  // all at once, as take_checkpoint
    if (!*file) continue;
    cosim::Message message;
    message.header.mutable_restore()->set_path((*file)->path);
    message.header.mutable_restore()->set_step((*file)->step);
    hub.send(peer, std::move(message));
  }
  for (const auto& [peer, file] : solvers) {
    if (!*file) continue;
    const auto reply = hub.receive_from(peer, timeout);
    if (!reply.header.has_restored())
      throw Error("solver '" + std::string(peer) + "' answered Restore with '" +
                  std::string(cosim::body_name(reply.header)) + "'");
    if (reply.header.restored().step() != (*file)->step)
      throw Error("solver '" + std::string(peer) + "' restored '" + (*file)->path + "' at step " +
                  std::to_string(reply.header.restored().step()) + "; the coupler checkpoint '" +
                  from.file.string() + "' names step " + std::to_string((*file)->step));
    Logger("coupler").info("solver '", peer, "' restored '", (*file)->path, "' (step ",
                           (*file)->step, ", t = ", reply.header.restored().time(), " s)");
  }
}

}  // namespace mpfd::coupler
