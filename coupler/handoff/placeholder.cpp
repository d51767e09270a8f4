#include "coupler/handoff/placeholder.hpp"

#include <cmath>
#include <string>

#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "common/eos/any_eos.hpp"
#include "coupler/handoff/sub_cell_centres.hpp"

namespace mpfd::coupler::handoff {
namespace {

void require_in_grid(const grid::UniformGrid& grid, const CellBox& box, const char* what) {
  for (int a = 0; a < 3; ++a)
    if (box.lo[a] < 0 || box.hi[a] > grid.cells()[a] || box.lo[a] > box.hi[a])
      throw Error(std::string(what) + ": box " + cell_box_text(box) + " must lie in the grid's " +
                  std::to_string(grid.cells()[0]) + " x " + std::to_string(grid.cells()[1]) +
                  " x " + std::to_string(grid.cells()[2]) + " cells");
}

}  // namespace

AmbientState ambient_state(const config::Scene& scene) {
  const config::MaterialState& initial = scene.initial;
  const config::Material* material = config::find_material(scene, initial.material);
  if (material == nullptr)
    throw Error("scene '" + scene.name + "': initial: unknown material '" + initial.material + "'");
  AmbientState state;
  state.material = static_cast<int>(material - scene.materials.data());
  state.density = initial.density;
  state.velocity = initial.velocity;
  state.specific_internal_energy =
      initial.specific_internal_energy
          ? *initial.specific_internal_energy
          : eos::internal_energy(material->eos, initial.density, initial.pressure.value_or(0.0));
  if (!(state.density > 0.0) || !std::isfinite(state.specific_internal_energy))
    throw Error("scene '" + scene.name + "': initial: material '" + initial.material +
                "' needs density > 0 and a reachable pressure, got density " +
                shortest_text(state.density));
  return state;
}

void fill_ambient_cells(const grid::UniformGrid& grid, const CellBox& box,
                        const AmbientState& state, ConservedCells& cells) {
  require_in_grid(grid, box, "fill_ambient_cells");
  check_sizes(cells.view(), grid.cell_count());
  double v2 = 0.0;
  for (const double v : state.velocity) v2 += v * v;
  const double energy = state.density * (state.specific_internal_energy + 0.5 * v2);  // T (2-49)
  for (int k = box.lo[2]; k < box.hi[2]; ++k)
    for (int j = box.lo[1]; j < box.hi[1]; ++j)
      for (int i = box.lo[0]; i < box.hi[0]; ++i) {
        const std::size_t c = grid.cell_index(i, j, k);
        cells.density[c] = state.density;
        for (int a = 0; a < 3; ++a) cells.momentum[a][c] = state.density * state.velocity[a];
        cells.total_energy[c] = energy;
      }
}

void append_regular_tracers(const grid::UniformGrid& grid, const CellBox& box, int material,
                            int tracers_per_axis, TracerPoints& tracers) {
  require_in_grid(grid, box, "append_regular_tracers");
  if (tracers_per_axis < 1)
    throw Error("append_regular_tracers: tracers per cell and axis must be >= 1, got " +
                std::to_string(tracers_per_axis));
  const std::size_t added = box.count() * sub_cell_count(grid, tracers_per_axis);
  for (auto& x : tracers.position) x.reserve(x.size() + added);
  tracers.material.reserve(tracers.material.size() + added);
  for (int k = box.lo[2]; k < box.hi[2]; ++k)
    for (int j = box.lo[1]; j < box.hi[1]; ++j)
      for (int i = box.lo[0]; i < box.hi[0]; ++i)
        for_each_sub_cell_centre(grid, {i, j, k}, tracers_per_axis, [&](const grid::Vec3& x) {
          for (int a = 0; a < 3; ++a) tracers.position[a].push_back(x[a]);
          tracers.material.push_back(material);
        });
}

}  // namespace mpfd::coupler::handoff
