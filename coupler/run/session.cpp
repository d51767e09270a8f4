#include "coupler/run/session.hpp"

#include <algorithm>
#include <cstdio>
#include <random>

#include "common/core/error.hpp"
#include "common/core/log.hpp"
#include "cosim/recorder.hpp"

namespace mpfd::coupler {

std::string make_run_id() {
  std::random_device device;
  char text[17];
  std::snprintf(text, sizeof text, "%08x%08x", device(), device());
  return text;
}

int grid_dimension(const config::Scene& scene) {
  int dimension = 0;
  for (const int cells : scene.domain.cells) dimension += cells > 1 ? 1 : 0;
  return dimension;
}

v1::UniformGrid wire_grid(const config::Scene& scene) {
  v1::UniformGrid grid;
  for (int a = 0; a < 3; ++a) {
    grid.add_origin(scene.domain.lower[a]);
    grid.add_spacing((scene.domain.upper[a] - scene.domain.lower[a]) / scene.domain.cells[a]);
    grid.add_cells(static_cast<std::uint64_t>(scene.domain.cells[a]));
  }
  grid.set_dimension(static_cast<std::uint32_t>(grid_dimension(scene)));
  return grid;
}

bool offers(const v1::Hello& hello, std::string_view capability) {
  const auto& list = hello.capabilities();
  return std::find(list.begin(), list.end(), capability) != list.end();
}

double advance_seconds(const cosim::Message& reply) {
  if (!reply.header.has_exchange_result()) return 0;
  for (const auto& result : reply.header.exchange_result().results())
    if (result.has_advanced()) return result.advanced().wall_seconds();
  return 0;
}

std::string shut_down(cosim::Hub& hub, std::vector<std::unique_ptr<SolverHandle>>& solvers,
                      const std::string& reason, const std::set<std::string>& already_shut) {
  for (const auto& solver : solvers) {
    // A solver that reported a fatal error has stopped or is stopping: a Shutdown
    // to it would wait a whole reply timeout for an answer that never comes.
    if (already_shut.contains(solver->name()) || hub.reported_fatal_error(solver->name()) ||
        solver->ended())
      continue;
    try {
      cosim::Message message;
      message.header.mutable_shutdown()->set_reason(reason);
      hub.send(solver->name(), std::move(message));
      (void)hub.receive_from(solver->name());
    } catch (const std::exception&) {
      // It is gone or broken; finish() below ends it.
    }
  }
  std::string how;
  for (const auto& solver : solvers)
    how += "; solver '" + solver->name() + "' " + solver->finish(std::chrono::milliseconds(2000));
  return how;
}

CoupledRunReport run_session(const config::Scene& scene, cosim::Hub& hub,
                             std::vector<std::unique_ptr<SolverHandle>>& solvers,
                             const CoupledRunOptions& options, const SessionBody& body) {
  const Logger logger("coupler");
  const std::vector<std::string> peers = {"fdm", "mpm"};
  std::unique_ptr<cosim::Recorder> recorder;
  if (options.record) {
    recorder = std::make_unique<cosim::Recorder>(*options.record);
    hub.attach_recorder(recorder.get());
  }
  io::RunSummary summary("coupler run", scene.name, options.scene_file);
  std::filesystem::create_directories(options.out_dir / "fdm");
  std::filesystem::create_directories(options.out_dir / "mpm");
  CoupledRunReport report;
  std::set<std::string> retired;
  // A solver that ends without a word (killed, crashed) is named within a fraction
  // of a second, not after a whole reply timeout; the catch below says how it ended.
  hub.set_watch([&] {
    for (const auto& solver : solvers)
      if (!hub.sent_shutdown(solver->name()) && !hub.reported_fatal_error(solver->name()) &&
          solver->ended())
        throw Error("solver '" + solver->name() + "' ended while the coupler waited for it");
  });
  try {
    const auto hellos = hub.accept(peers, make_run_id());
    for (std::size_t i = 0; i < hellos.size(); ++i)
      logger.info("solver '", peers[i], "': ", hellos[i].software(), " pid ", hellos[i].pid());
    report = body(hellos, summary, retired);
  } catch (const std::exception& error) {
    hub.set_watch({});
    std::string ended;
    for (const auto& solver : solvers)
      if (const auto how = solver->ended()) ended += "; solver '" + solver->name() + "' " + *how;
    const std::string text = std::string(error.what()) + ended;
    summary.set_status("failed", text);
    summary.write(options.out_dir / "summary.json");
    shut_down(hub, solvers, "coupler stops: " + text, retired);
    hub.attach_recorder(nullptr);
    if (recorder) recorder->close();
    throw Error("coupler run failed: " + text);
  }
  hub.set_watch({});
  shut_down(hub, solvers, "run completed", retired);
  hub.attach_recorder(nullptr);
  if (recorder) recorder->close();
  return report;
}

}  // namespace mpfd::coupler
