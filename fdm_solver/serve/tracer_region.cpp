#include "fdm_solver/serve/tracer_region.hpp"

#include <algorithm>
#include <cstdint>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "fdm_solver/serve/cell_region.hpp"
#include "fdm_solver/tracer/cell_lookup.hpp"

namespace mpfd::fdm {

std::string_view tracer_quantity_name(TracerQuantity q) {
  return q == TracerQuantity::position ? "position" : "material";
}

std::optional<TracerQuantity> find_tracer_quantity(std::string_view name) {
  for (const TracerQuantity q : {TracerQuantity::position, TracerQuantity::material})
    if (tracer_quantity_name(q) == name) return q;
  return std::nullopt;
}

bool TracerRegion::declares(TracerQuantity q) const {
  return std::find(quantities.begin(), quantities.end(), q) != quantities.end();
}

bool TracerRegion::holds(const grid::UniformGrid& grid, const grid::Vec3& x) const {
  const grid::Index3 cell = grid.cell_of_index(cell_holding(grid, x));
  for (int a = 0; a < 3; ++a)
    if (cell[a] < box.lower[a] || cell[a] >= box.upper[a]) return false;
  return true;
}

TracerRegion make_tracer_region(const cosim::v1::Region& region, const grid::UniformGrid& grid) {
  // The box obeys the rules of a CELLS box; check it as one.
  cosim::v1::Region cells = region;
  cells.set_kind(cosim::v1::REGION_KIND_CELLS);
  cells.clear_quantities();
  TracerRegion tracers{region.name(), make_cell_region(cells, grid).box, {}};
  for (const auto& name : region.quantities()) {
    const auto q = find_tracer_quantity(name);
    if (!q)
      throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                                 "Setup region '" + region.name() + "': unknown quantity '" + name +
                                     "' of a TRACERS region; known: position, material");
    tracers.quantities.push_back(*q);
  }
  if (tracers.quantities.empty())
    tracers.quantities = {TracerQuantity::position, TracerQuantity::material};
  return tracers;
}

std::uint64_t export_tracers(const EulerSolver& solver, const TracerRegion& region,
                             std::span<const std::string> quantities, cosim::Message& reply) {
  std::vector<TracerQuantity> asked;
  for (const auto& name : quantities) {
    const auto q = find_tracer_quantity(name);
    if (!q || !region.declares(*q))
      throw cosim::ProtocolError(cosim::v1::ERROR_CODE_UNKNOWN_REGION,
                                 "region '" + region.name + "', quantity '" + name +
                                     "': not declared for it in Setup, so it cannot be exported");
    asked.push_back(*q);
  }
  if (asked.empty()) asked = region.quantities;
  const grid::UniformGrid& grid = solver.state().grid;
  std::vector<std::size_t> inside;
  // A one-material zone has no tracker and so no tracers: every array is empty.
  const TracerSet* tracers = solver.tracker() ? &solver.tracker()->tracers() : nullptr;
  if (tracers != nullptr) {
    const TracerSet& t = *tracers;
    for (std::size_t n = 0; n < t.size(); ++n)
      if (region.holds(grid, {t.position[0][n], t.position[1][n], t.position[2][n]}))
        inside.push_back(n);
  }
  const std::uint64_t count = inside.size();
  for (const TracerQuantity q : asked) {
    const cosim::ArraySpec spec{
        region.name, tracer_quantity_name(q),
        q == TracerQuantity::position ? cosim::ArrayShape{count, 3} : cosim::ArrayShape{count},
        q == TracerQuantity::position ? "m" : ""};
    if (q == TracerQuantity::position) {
      std::vector<double> position(3 * count);
      for (std::size_t n = 0; n < count; ++n)  // count > 0 only with tracers
        for (int a = 0; a < 3; ++a) position[3 * n + a] = tracers->position[a][inside[n]];
      cosim::add_array(reply, spec, std::span<const double>(position));
    } else {
      std::vector<std::uint32_t> material(count);
      for (std::size_t n = 0; n < count; ++n)
        material[n] = static_cast<std::uint32_t>(tracers->material[inside[n]]);
      cosim::add_array(reply, spec, std::span<const std::uint32_t>(material));
    }
  }
  return count;
}

}  // namespace mpfd::fdm
