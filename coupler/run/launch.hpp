#pragma once
// How `coupler run` gets its two solvers: embedded (threads of this process
// over inproc), as child processes (over ipc, or over the given endpoints), or
// external (started by someone else; the coupler binds the given endpoints and
// waits for them to connect).

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "coupler/run/coupled_run.hpp"

namespace mpfd::coupler {

enum class LaunchMode { embedded, processes, external };

struct LaunchOptions {
  LaunchMode mode = LaunchMode::embedded;
  /// Bind endpoints per solver ("fdm", "mpm"); empty: chosen by the mode.
  std::map<std::string, std::string> endpoints;
  double timeout_seconds = 5.0;       ///< reply timeout (proto §1)
  std::filesystem::path fdm_program;  ///< for processes; empty: beside the coupler
  std::filesystem::path mpm_program;
  bool overwrite = false;
  /// Go on with the run in the output folder from its newest checkpoint.
  bool restart = false;
};

/// Parses "fdm=URL,mpm=URL"; throws mpfd::Error naming a bad entry.
[[nodiscard]] std::map<std::string, std::string> parse_endpoint_list(const std::string& text);

/// The log of solver program `program` started as a process for a run in `out_dir`:
/// <program>.log, or for a restart from coupled step `restart_step`
/// <program>_restart_<step>.log, then _2, _3, ... beside an earlier restart's, so that
/// no log of the stopped run or of an earlier restart is written over.
[[nodiscard]] std::filesystem::path solver_log_file(const std::filesystem::path& out_dir,
                                                    const std::string& program,
                                                    std::optional<std::int64_t> restart_step);

/// The in-process entry point of solver `name` ("fdm" or "mpm"); throws mpfd::Error otherwise.
[[nodiscard]] ServeFunction embedded_serve(const std::string& name);

/// Loads and checks the scene (a bad scene or layout is refused before
/// anything starts or is written), prepares the output folder (or, with
/// launch.restart, finds its newest checkpoint and keeps everything in it),
/// starts the solvers and runs. Throws mpfd::Error.
CoupledRunReport launch_run(const std::filesystem::path& scene_file, const LaunchOptions& launch,
                            CoupledRunOptions options, const std::filesystem::path& self);

}  // namespace mpfd::coupler
