#include "fdm_solver/serve/material_quantities.hpp"

#include <array>
#include <cstdint>
#include <vector>

#include "cosim/arrays.hpp"
#include "fdm_solver/serve/cell_region.hpp"

namespace mpfd::fdm {
namespace {

constexpr std::array<MaterialQuantity, 4> kAll{
    MaterialQuantity::cell_material, MaterialQuantity::volume_fraction,
    MaterialQuantity::material_density, MaterialQuantity::material_energy};

/// Writes the `materials` values of quantity q (not cell_material) of `cell` into out.
void per_material_values(const EulerSolver& solver, MaterialQuantity q, std::size_t cell,
                         double* out) {
  const EulerState& state = solver.state();
  const std::size_t materials = solver.materials().size();
  for (std::size_t r = 0; r < materials; ++r) out[r] = 0.0;
  const MultiMaterialTracker* tracker = solver.tracker();
  if (tracker == nullptr || !tracker->materials().is_mixed(cell)) {
    const std::size_t m = tracker ? static_cast<std::size_t>(tracker->materials().material[cell])
                                  : state.material[cell];
    out[m] = q == MaterialQuantity::volume_fraction    ? 1.0
             : q == MaterialQuantity::material_density ? state.u[kDensity][cell]
                                                       : specific_internal_energy(state, cell);
    return;
  }
  const MaterialMap& map = tracker->materials();
  const MaterialStates& parts = tracker->states();
  for (std::size_t r = 0; r < materials; ++r) {
    const double theta = map.volume_fraction(cell, static_cast<int>(r));
    if (theta <= 0.0) continue;
    const std::size_t k = parts.at(static_cast<int>(r), cell);
    out[r] = q == MaterialQuantity::volume_fraction    ? theta
             : q == MaterialQuantity::material_density ? parts.density[k]
                                                       : parts.energy[k];
  }
}

}  // namespace

std::string_view material_quantity_name(MaterialQuantity q) {
  switch (q) {
    case MaterialQuantity::cell_material:
      return "cell_material";
    case MaterialQuantity::volume_fraction:
      return "volume_fraction";
    case MaterialQuantity::material_density:
      return "material_density";
    case MaterialQuantity::material_energy:
      return "material_energy";
  }
  return "";
}

std::optional<MaterialQuantity> find_material_quantity(std::string_view name) {
  for (const MaterialQuantity q : kAll)
    if (material_quantity_name(q) == name) return q;
  return std::nullopt;
}

void export_material_quantity(const EulerSolver& solver, std::string_view group,
                              const ActiveBox& box, MaterialQuantity q, cosim::Message& reply) {
  const EulerState& state = solver.state();
  const auto count = static_cast<std::size_t>(box.cells());
  const std::string_view name = material_quantity_name(q);
  if (q == MaterialQuantity::cell_material) {
    std::vector<std::int32_t> material(count);
    const MultiMaterialTracker* tracker = solver.tracker();
    for_each_transfer_cell(state.grid, box, [&](std::size_t n, std::size_t cell) {
      material[n] = tracker ? tracker->materials().material[cell]  // kMixedCell = -1
                            : static_cast<std::int32_t>(state.material[cell]);
    });
    cosim::add_array(reply, {group, name, {}, ""}, std::span<const std::int32_t>(material));
    return;
  }
  const std::size_t materials = solver.materials().size();
  std::vector<double> values(count * materials);
  for_each_transfer_cell(state.grid, box, [&](std::size_t n, std::size_t cell) {
    per_material_values(solver, q, cell, values.data() + n * materials);
  });
  const std::string_view units = q == MaterialQuantity::volume_fraction    ? ""
                                 : q == MaterialQuantity::material_density ? "kg/m^3"
                                                                           : "J/kg";
  cosim::add_array(reply, {group, name, {count, materials}, units},
                   std::span<const double>(values));
}

}  // namespace mpfd::fdm
