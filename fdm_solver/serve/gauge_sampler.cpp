#include "fdm_solver/serve/gauge_sampler.hpp"

#include <array>
#include <cstring>
#include <optional>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/cell_quantities.hpp"

namespace mpfd::fdm {
namespace {

struct GaugeQuantity {
  Quantity quantity;
  std::size_t component;
};

/// "pressure" -> (pressure, 0); "velocity_y" -> (velocity, 1).
std::optional<GaugeQuantity> parse_gauge_quantity(std::string_view name) {
  if (const auto q = find_quantity(name); q && info(*q).components == 1) return {{*q, 0}};
  constexpr std::string_view suffixes[3] = {"_x", "_y", "_z"};
  for (std::size_t c = 0; c < 3; ++c) {
    if (!name.ends_with(suffixes[c])) continue;
    const auto q = find_quantity(name.substr(0, name.size() - 2));
    if (q && info(*q).components == 3) return {{*q, c}};
  }
  return std::nullopt;
}

[[noreturn]] void reject(const cosim::v1::SampleGauges& request, const std::string& rule) {
  throw cosim::ProtocolError(cosim::v1::ERROR_CODE_MALFORMED,
                             "SampleGauges group '" + request.group() + "': " + rule);
}

}  // namespace

std::uint64_t sample_gauges(const EulerSolver& solver, const cosim::v1::SampleGauges& request,
                            cosim::Message& reply) {
  const auto& grid = solver.state().grid;
  const std::size_t n = static_cast<std::size_t>(request.gauge_names_size());
  const std::size_t coordinates = static_cast<std::size_t>(request.positions_size());
  const std::size_t d = n == 0 ? 3 : coordinates / n;
  if (d * n != coordinates || d < 1 || d > 3)
    reject(request, std::to_string(coordinates) + " position values for " + std::to_string(n) +
                        " gauges; expected 1, 2 or 3 coordinates per gauge");
  for (std::size_t a = d; a < 3; ++a)
    if (grid.cells()[a] != 1)
      reject(request, "positions give " + std::to_string(d) + " coordinates but axis " +
                          std::to_string(a) + " has " + std::to_string(grid.cells()[a]) + " cells");

  const auto cell_of = [&](std::size_t g) -> std::optional<std::size_t> {
    grid::Vec3 point{};
    for (std::size_t a = 0; a < 3; ++a)
      point[a] = a < d ? request.positions(static_cast<int>(g * d + a))
                       : grid.origin()[a] + 0.5 * grid.spacing()[a];
    const auto where = grid.locate(point);
    if (!where) return std::nullopt;
    return grid.cell_index(where->cell);
  };
  for (std::size_t g = 0; g < n; ++g)
    if (!cell_of(g))
      reject(request,
             "gauge '" + request.gauge_names(static_cast<int>(g)) + "' lies outside the grid");

  for (const auto& name : request.quantities()) {
    const auto q = parse_gauge_quantity(name);
    if (!q)
      reject(request, "unknown quantity '" + name +
                          "'; known: rho, E, pressure, momentum_x|y|z, velocity_x|y|z");
    zmq::message_t frame(n * sizeof(double));
    auto* out = static_cast<std::byte*>(frame.data());
    std::array<double, 3> values{};
    for (std::size_t g = 0; g < n; ++g) {
      cell_values(solver.state(), solver.materials(), q->quantity, *cell_of(g), values);
      std::memcpy(out + g * sizeof(double), &values[q->component], sizeof(double));
    }
    const std::string_view units = info(q->quantity).units;
    cosim::append_frame(reply, {request.group(), name, {}, units}, cosim::v1::DTYPE_F64, n,
                        std::move(frame));
  }
  return n;
}

}  // namespace mpfd::fdm
