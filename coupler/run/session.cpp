#include "coupler/run/session.hpp"

#include <algorithm>
#include <cstdio>
#include <random>

namespace mpfd::coupler {

std::string make_run_id() {
  std::random_device device;
  char text[17];
  std::snprintf(text, sizeof text, "%08x%08x", device(), device());
  return text;
}

v1::UniformGrid wire_grid(const config::Scene& scene) {
  v1::UniformGrid grid;
  int dimension = 0;
  for (int a = 0; a < 3; ++a) {
    grid.add_origin(scene.domain.lower[a]);
    grid.add_spacing((scene.domain.upper[a] - scene.domain.lower[a]) / scene.domain.cells[a]);
    grid.add_cells(static_cast<std::uint64_t>(scene.domain.cells[a]));
    dimension += scene.domain.cells[a] > 1 ? 1 : 0;
  }
  grid.set_dimension(static_cast<std::uint32_t>(dimension));
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
                      const std::string& reason) {
  for (const auto& solver : solvers) {
    if (solver->ended()) continue;
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

}  // namespace mpfd::coupler
