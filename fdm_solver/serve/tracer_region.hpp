#pragma once
// A named TRACERS region declared in Setup (proto/README.md §15, v1.2): the
// massless tracers of the zone inside a half-open box [lo, hi) of interior
// cells (a tracer belongs to the cell that bins it, cell_lookup.hpp), with
// quantities `position` (F64 [n, 3], m) and `material` (U32 [n], the scene's
// material index), in tracer order.

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "cosim/message.hpp"
#include "fdm_solver/active_box.hpp"
#include "fdm_solver/euler_solver.hpp"

namespace mpfd::fdm {

enum class TracerQuantity { position, material };

[[nodiscard]] std::string_view tracer_quantity_name(TracerQuantity q);
[[nodiscard]] std::optional<TracerQuantity> find_tracer_quantity(std::string_view name);

struct TracerRegion {
  std::string name;
  ActiveBox box;
  std::vector<TracerQuantity> quantities;

  [[nodiscard]] bool declares(TracerQuantity q) const;
  /// The tracer at `x` lies in a cell of the box.
  [[nodiscard]] bool holds(const grid::UniformGrid& grid, const grid::Vec3& x) const;
};

/// Checks a Setup region of kind TRACERS against `grid`: its box as
/// make_cell_region checks a CELLS box, quantities position and material (none
/// given: both). Throws cosim::ProtocolError{UNKNOWN_REGION} naming the region.
[[nodiscard]] TracerRegion make_tracer_region(const cosim::v1::Region& region,
                                              const grid::UniformGrid& grid);

/// Appends the asked quantities (none: the region's) of the solver's tracers
/// in the region's box, in tracer order (a one-material solver has none: the
/// arrays have 0 rows). Returns the tracer count. Throws
/// cosim::ProtocolError{UNKNOWN_REGION} for a quantity the region does not declare.
std::uint64_t export_tracers(const EulerSolver& solver, const TracerRegion& region,
                             std::span<const std::string> quantities, cosim::Message& reply);

}  // namespace mpfd::fdm
