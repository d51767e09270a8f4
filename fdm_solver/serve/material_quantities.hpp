#pragma once
// The per-material cell quantities an Euler zone exports (proto/README.md
// §15 rule 6, v1.2; all but cell_material are also imported as a mixed-cell
// start, rule 8, field_import.hpp): `cell_material` (I32 [n], the material of a
// single-material cell, -1 for a mixed one), and, F64 [n, materials] with the
// scene's materials last, `volume_fraction` theta_r, `material_density` rho_r
// [kg/m^3] and `material_energy` e_r [J/kg]. A single-material cell has theta
// = 1 for its material, rho_r = rho and e_r = e; a mixed cell the tracker's
// theta_r (T (3-23)) and the closure's rho_r, e_r (T (3-24)-(3-28)); a
// material absent from a cell has 0 for all three.

#include <optional>
#include <string>
#include <string_view>

#include "cosim/message.hpp"
#include "fdm_solver/active_box.hpp"
#include "fdm_solver/euler_solver.hpp"

namespace mpfd::fdm {

enum class MaterialQuantity { cell_material, volume_fraction, material_density, material_energy };

[[nodiscard]] std::string_view material_quantity_name(MaterialQuantity q);
/// The quantity called `name`, or nothing.
[[nodiscard]] std::optional<MaterialQuantity> find_material_quantity(std::string_view name);

/// Appends quantity `q` of the cells of `box` (box C order, k fastest) as
/// array `group`/name to `reply`.
void export_material_quantity(const EulerSolver& solver, std::string_view group,
                              const ActiveBox& box, MaterialQuantity q, cosim::Message& reply);

}  // namespace mpfd::fdm
