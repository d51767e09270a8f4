#include "fdm_solver/serve/tracker_checkpoint.hpp"

#include <array>
#include <string>
#include <vector>

namespace mpfd::fdm {
namespace {

constexpr std::array<const char*, 3> kPosition = {"/tracers/position_x", "/tracers/position_y",
                                                  "/tracers/position_z"};

std::vector<std::size_t> tracker_cell_shape(const grid::UniformGrid& grid) {
  const auto& n = grid.cells();
  return {static_cast<std::size_t>(n[2]), static_cast<std::size_t>(n[1]),
          static_cast<std::size_t>(n[0])};
}

template <class T>
std::vector<std::int64_t> as_int64(const std::vector<T>& values) {
  std::vector<std::int64_t> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) out[i] = static_cast<std::int64_t>(values[i]);
  return out;
}

}  // namespace

void write_tracker_state(io::Hdf5File& h5, const MultiMaterialTracker& tracker,
                         const grid::UniformGrid& grid) {
  const TracerSet& tracers = tracker.tracers();
  const std::vector<std::size_t> per_tracer = {tracers.size()};
  h5.create_group("/tracers");
  for (std::size_t a = 0; a < 3; ++a)
    h5.write_dataset(kPosition[a], tracers.position[a], per_tracer, "m");
  h5.write_dataset("/tracers/material", as_int64(tracers.material), per_tracer);
  h5.write_dataset("/tracers/volume", tracers.volume, per_tracer, "m^3");

  const MaterialMap& map = tracker.materials();
  const MaterialStates& states = tracker.states();
  const auto cells = tracker_cell_shape(grid);
  auto per_material = cells;
  per_material.insert(per_material.begin(), static_cast<std::size_t>(map.material_count));
  h5.create_group("/materials");
  h5.write_dataset("/materials/cell_material", as_int64(map.material), cells);
  h5.write_dataset("/materials/theta", map.theta, per_material, "1");
  h5.write_dataset("/materials/energy", states.energy, per_material, "J/kg");
  h5.write_dataset("/materials/density", states.density, per_material, "kg/m^3");
  h5.write_dataset("/materials/cell_energy", states.cell_energy, cells, "J/kg");
  h5.write_dataset("/materials/closure_status", as_int64(states.status), cells);
}

TrackerState read_tracker_state(const cosim::CheckpointReader& reader,
                                const grid::UniformGrid& grid, int materials) {
  const std::size_t cells = grid.cell_count();
  const std::size_t per_material = static_cast<std::size_t>(materials) * cells;
  const std::string range = "a material index in [0, " + std::to_string(materials) + ")";
  if (!reader.file().exists("/tracers/volume"))
    reader.mismatch("holds no tracers (array '/tracers/volume'); the running zone has " +
                    std::to_string(materials) + " materials and tracers");
  TrackerState s;
  s.tracers.volume = reader.file().read_dataset("/tracers/volume").values;  // n: its length
  const std::size_t n = s.tracers.volume.size();
  s.tracers.material =
      reader.indices("/tracers/material", n, "one per tracer", materials, std::nullopt, range);
  for (std::size_t a = 0; a < 3; ++a)
    s.tracers.position[a] = reader.values(kPosition[a], n, "one per tracer");

  s.materials.material_count = materials;
  s.materials.material = reader.indices("/materials/cell_material", cells, "one per cell",
                                        materials, kMixedCell, range + " or -1 (mixed)");
  s.materials.theta = reader.values("/materials/theta", per_material, "materials x cells");

  s.states.cell_count = cells;
  s.states.energy = reader.values("/materials/energy", per_material, "materials x cells");
  s.states.density = reader.values("/materials/density", per_material, "materials x cells");
  s.states.cell_energy = reader.values("/materials/cell_energy", cells, "one per cell");
  const auto status = reader.indices(
      "/materials/closure_status", cells, "one per cell",
      static_cast<int>(ClosureStatus::fallback) + 1, std::nullopt,
      "a closure status 0-3 (single material, converged, iteration limit, fallback)");
  s.states.status.resize(cells);
  for (std::size_t c = 0; c < cells; ++c)
    s.states.status[c] = static_cast<ClosureStatus>(status[c]);
  return s;
}

}  // namespace mpfd::fdm
