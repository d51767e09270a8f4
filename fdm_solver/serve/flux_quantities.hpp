#pragma once
// Protocol v1.1 amounts that crossed faces (proto/README.md §14), as opposed to
// the cell values of cell_quantities.hpp:
//   crossed_mass [kg], crossed_momentum [kg m/s, n x 3], crossed_energy [J]: per
//     face of a FACES region (the coupling face), what the sweeps put through it
//     toward +face_axis since the region's last export (its Advances);
//   outflow_mass, outflow_momentum [1 x 3], outflow_energy: one value per CELLS
//     region, what has left the domain through the domain faces of its cells
//     since Setup (momentum: also the impulse of walls, as EulerSolver::outflow()).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "cosim/message.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/serve/cell_region.hpp"

namespace mpfd::fdm {

enum class FluxQuantity {
  crossed_mass,
  crossed_momentum,
  crossed_energy,
  outflow_mass,
  outflow_momentum,
  outflow_energy
};

struct FluxQuantityInfo {
  std::string_view name;
  std::size_t components;  ///< 1, or 3 (x, y, z)
  std::string_view units;
  std::size_t variable;  ///< first of its EulerState variables (kDensity ...)
  bool on_faces;         ///< FACES regions; else one total per CELLS region
};

[[nodiscard]] const FluxQuantityInfo& info(FluxQuantity q);
[[nodiscard]] std::optional<FluxQuantity> find_flux_quantity(std::string_view name);
[[nodiscard]] std::string flux_quantity_names();

/// Appends the array of `q` for `region` to `reply` (group region.name):
/// crossed_* per face in box C order, outflow_* as one row. Returns its rows.
std::uint64_t export_flux(const EulerSolver& solver, const CellRegion& region, FluxQuantity q,
                          cosim::Message& reply);

}  // namespace mpfd::fdm
