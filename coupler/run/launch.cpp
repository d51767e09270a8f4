#include "coupler/run/launch.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "common/io/output_directory.hpp"
#include "coupler/run/afdmp_layout.hpp"
#include "coupler/run/afdmp_run.hpp"
#include "coupler/run/gauges.hpp"
#include "coupler/run/session.hpp"
#include "coupler/run/zone_layout.hpp"
#include "fdm_solver/serve/serve.hpp"
#include "mpm_solver/serve/serve.hpp"

namespace mpfd::coupler {
namespace {

// Embedded solvers stop at their idle timeout if the coupler vanishes.
constexpr std::chrono::milliseconds kEmbeddedIdle{60000};

void serve_fdm(zmq::context_t& context, const std::string& endpoint, const std::string& name) {
  fdm::serve(context, {.endpoint = endpoint, .name = name, .idle_timeout = kEmbeddedIdle});
}

void serve_mpm(zmq::context_t& context, const std::string& endpoint, const std::string& name) {
  mpm::serve(context, {.endpoint = endpoint, .name = name, .idle_timeout = kEmbeddedIdle});
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw Error("cannot read scene file '" + file.string() + "'");
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// A solver program: given, else beside the coupler, else in the build tree's folder.
std::filesystem::path program(const std::filesystem::path& given, const std::filesystem::path& self,
                              const std::string& name) {
  if (!given.empty()) return given;
  const auto dir = self.parent_path();
  for (const auto& candidate : {dir / name, dir.parent_path() / name / name})
    if (std::filesystem::exists(candidate)) return candidate;
  throw Error("cannot find the " + name + " program beside " + self.string() + " or in ../" + name +
              "/; give it with --" + (name == "fdm_solver" ? "fdm" : "mpm") + "-program");
}

}  // namespace

std::filesystem::path solver_log_file(const std::filesystem::path& out_dir,
                                      const std::string& program,
                                      std::optional<std::int64_t> restart_step) {
  if (!restart_step) return out_dir / (program + ".log");
  const std::string stem = program + "_restart_" + std::to_string(*restart_step);
  std::filesystem::path file = out_dir / (stem + ".log");
  for (int n = 2; std::filesystem::exists(file); ++n)
    file = out_dir / (stem + "_" + std::to_string(n) + ".log");
  return file;
}

ServeFunction embedded_serve(const std::string& name) {
  if (name == "fdm") return serve_fdm;
  if (name == "mpm") return serve_mpm;
  throw Error("no solver called '" + name + "' (expected fdm or mpm)");
}

std::map<std::string, std::string> parse_endpoint_list(const std::string& text) {
  std::map<std::string, std::string> endpoints;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto eq = item.find('=');
    const std::string name = item.substr(0, eq);
    if (eq == std::string::npos || (name != "fdm" && name != "mpm") || eq + 1 == item.size())
      throw Error("--endpoints: expected fdm=URL,mpm=URL, got '" + item + "'");
    endpoints[name] = item.substr(eq + 1);
  }
  return endpoints;
}

CoupledRunReport launch_run(const std::filesystem::path& scene_file, const LaunchOptions& launch,
                            CoupledRunOptions options, const std::filesystem::path& self) {
  const std::string text = read_text(scene_file);
  const config::Scene scene = config::parse_scene(text, scene_file.string());
  // Refuse a scene the coupler cannot drive before anything starts.
  const bool afdmp = scene.solver.method == config::Method::afdmp;
  if (afdmp)
    (void)make_afdmp_layout(scene);
  else
    (void)make_zone_layout(scene);
  for (const auto& gauge : scene.gauges) (void)gauge_owner(scene, gauge);
  if (launch.mode == LaunchMode::external &&
      (!launch.endpoints.contains("fdm") || !launch.endpoints.contains("mpm")))
    throw Error("external solvers need --endpoints fdm=URL,mpm=URL");
  std::filesystem::path fdm_program, mpm_program;
  if (launch.mode == LaunchMode::processes) {
    fdm_program = program(launch.fdm_program, self, "fdm_solver");
    mpm_program = program(launch.mpm_program, self, "mpm_solver");
  }
  if (options.checkpoint_keep < 0)
    throw Error("--checkpoint-keep " + std::to_string(options.checkpoint_keep) +
                ": expected a whole number >= 0 (0: keep every checkpoint)");
  if (options.checkpoint_every < 0)
    throw Error("--checkpoint-every " + std::to_string(options.checkpoint_every) +
                ": expected a count of outputs >= 0 (0: none)");
  if (launch.restart) {
    if (launch.overwrite)
      throw Error(
          "--restart goes on with the run in --out; --overwrite would start a new one "
          "there: give one of the two");
    options.restart = newest_checkpoint(options.out_dir, text, grid_dimension(scene));
  } else {
    io::prepare_output_directory(options.out_dir, launch.overwrite);
    remove_checkpoints(options.out_dir);  // an earlier run's, where --overwrite reuses its folder
  }
  options.scene_file = scene_file;

  cosim::TransportOptions transport;
  transport.reply_timeout = std::chrono::milliseconds(std::llround(launch.timeout_seconds * 1e3));
  zmq::context_t context;
  std::map<std::string, std::string> endpoints = launch.endpoints;
  const std::string tag = std::to_string(::getpid());
  for (const char* name : {"fdm", "mpm"}) {
    if (endpoints.contains(name)) continue;
    endpoints[name] =
        launch.mode == LaunchMode::processes
            ? "ipc://" + (std::filesystem::temp_directory_path() / ("mpfd-coupler-" + tag)).string()
            : "inproc://mpfd-coupler-" + tag;
  }
  cosim::Hub hub(context, endpoints["fdm"], transport);
  std::string mpm_endpoint = hub.endpoint();
  if (endpoints["mpm"] != endpoints["fdm"]) mpm_endpoint = hub.bind_also(endpoints["mpm"]);
  const std::map<std::string, std::string> connect = {{"fdm", hub.endpoint()},
                                                      {"mpm", mpm_endpoint}};

  std::vector<std::unique_ptr<SolverHandle>> solvers;
  // A solver waiting through an AFDMP handoff hears nothing for up to --handoff-timeout.
  const double handoff_seconds = std::chrono::duration<double>(options.handoff_timeout).count();
  const std::string idle =
      std::to_string(std::max({10.0, 4 * launch.timeout_seconds, handoff_seconds}));
  // A restart keeps the stopped run's logs, which may say why it stopped.
  const auto log = [&](const std::string& program) {
    return solver_log_file(options.out_dir, program,
                           options.restart ? std::optional(options.restart->step) : std::nullopt)
        .string();
  };
  if (launch.mode == LaunchMode::processes) {
    solvers.push_back(start_process(
        "fdm",
        {fdm_program.string(), "serve", "--endpoint", connect.at("fdm"), "--idle-timeout", idle},
        log("fdm_solver")));
    solvers.push_back(start_process(
        "mpm",
        {mpm_program.string(), "serve", "--endpoint", connect.at("mpm"), "--idle-timeout", idle},
        log("mpm_solver")));
  } else if (launch.mode == LaunchMode::embedded) {
    solvers.push_back(start_thread("fdm", serve_fdm, context, connect.at("fdm")));
    solvers.push_back(start_thread("mpm", serve_mpm, context, connect.at("mpm")));
  } else {
    solvers.push_back(external_solver("fdm"));
    solvers.push_back(external_solver("mpm"));
  }
  return afdmp ? run_afdmp(scene, text, hub, solvers, options)
               : run_cfdmp(scene, text, hub, solvers, options);
}

}  // namespace mpfd::coupler
