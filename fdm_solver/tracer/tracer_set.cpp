#include "fdm_solver/tracer/tracer_set.hpp"

#include <cmath>
#include <string>

#include "common/core/error.hpp"

namespace mpfd::fdm {

void TracerSet::reserve(std::size_t n) {
  for (auto& x : position) x.reserve(n);
  material.reserve(n);
  volume.reserve(n);
}

void TracerSet::add(const grid::Vec3& x, int material_index, double carried_volume) {
  for (int a = 0; a < 3; ++a) position[a].push_back(x[a]);
  material.push_back(material_index);
  volume.push_back(carried_volume);
}

std::size_t TracerSet::compact() {
  std::size_t kept = 0;
  std::size_t lost = 0;
  for (std::size_t t = 0; t < size(); ++t) {
    if (material[t] < 0) {
      lost += material[t] == kLostTracer ? 1 : 0;
      continue;
    }
    for (auto& x : position) x[kept] = x[t];
    material[kept] = material[t];
    volume[kept] = volume[t];
    ++kept;
  }
  for (auto& x : position) x.resize(kept);
  material.resize(kept);
  volume.resize(kept);
  return lost;
}

std::vector<int> material_indices(std::span<const double> cell_material) {
  std::vector<int> out(cell_material.size());
  for (std::size_t c = 0; c < out.size(); ++c) {
    const double m = cell_material[c];
    if (!(m >= 0.0) || m != std::floor(m) || m > 1e9)
      throw Error("tracers: the material of cell " + std::to_string(c) +
                  " must be a whole number >= 0 (an index into materials), got " +
                  std::to_string(m));
    out[c] = static_cast<int>(m);
  }
  return out;
}

TracerSet seed_from_materials(const grid::UniformGrid& grid, std::span<const int> cell_material,
                              int n_per_axis) {
  if (n_per_axis < 1)
    throw Error("tracers: tracers per cell and axis must be >= 1, got " +
                std::to_string(n_per_axis));
  if (cell_material.size() != grid.cell_count())
    throw Error("tracers: the cell material array has " + std::to_string(cell_material.size()) +
                " entries, the grid " + std::to_string(grid.cell_count()) + " cells");
  grid::Index3 per_axis{};
  for (int a = 0; a < 3; ++a) per_axis[a] = grid.is_active(a) ? n_per_axis : 1;
  const std::size_t per_cell = static_cast<std::size_t>(per_axis[0]) * per_axis[1] * per_axis[2];
  const double volume = grid.cell_volume() / static_cast<double>(per_cell);  // T (3-21)

  TracerSet tracers;
  tracers.reserve(per_cell * grid.cell_count());
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    if (cell_material[c] < 0)
      throw Error("tracers: the material of cell " + std::to_string(c) + " must be >= 0, got " +
                  std::to_string(cell_material[c]));
    const grid::Index3 cell = grid.cell_of_index(c);
    for (int k = 0; k < per_axis[2]; ++k)
      for (int j = 0; j < per_axis[1]; ++j)
        for (int i = 0; i < per_axis[0]; ++i) {
          const grid::Index3 sub{i, j, k};
          grid::Vec3 x{};
          for (int a = 0; a < 3; ++a)
            x[a] = grid.origin()[a] + (cell[a] + (sub[a] + 0.5) / per_axis[a]) * grid.spacing()[a];
          tracers.add(x, cell_material[c], volume);
        }
  }
  return tracers;
}

TracerSet seed_from_materials(const grid::UniformGrid& grid, std::span<const double> cell_material,
                              int n_per_axis) {
  const std::vector<int> indices = material_indices(cell_material);
  return seed_from_materials(grid, std::span<const int>(indices), n_per_axis);
}

}  // namespace mpfd::fdm
