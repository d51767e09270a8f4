#include "coupler/remap/shell_material_sums.hpp"

#include <string>

#include "common/core/error.hpp"

namespace mpfd::coupler::remap {

handoff::MaterialSums shell_material_sums(const CartesianFields& f, double cell_volume,
                                          const handoff::AmbientState& ambient, int materials) {
  if (f.material_count > materials || ambient.material < 0 || ambient.material >= materials)
    throw Error("shell material sums: the profile holds " + std::to_string(f.material_count) +
                " materials and the ambient is material " + std::to_string(ambient.material) +
                "; the scene has " + std::to_string(materials));
  const std::size_t cells = f.covered_fraction.size();
  const auto to = static_cast<std::size_t>(materials);
  const auto from = static_cast<std::size_t>(f.material_count);
  handoff::MaterialSums sums(cells, materials);
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t r = 0; r < from; ++r) {
      const double theta = f.volume_fraction[c * from + r];
      if (!(theta > 0.0)) continue;
      sums.mass[c * to + r] = f.material_mass[c * from + r];
      sums.volume[c * to + r] = theta * cell_volume;
      sums.energy[c * to + r] = f.material_internal_energy[c * from + r];
      sums.contributors[c * to + r] = 1;
    }
    const double rest = 1.0 - f.covered_fraction[c];
    if (!(rest > 0.0)) continue;
    const std::size_t row = c * to + static_cast<std::size_t>(ambient.material);
    sums.mass[row] += rest * cell_volume * ambient.density;
    sums.volume[row] += rest * cell_volume;
    sums.energy[row] += rest * cell_volume * ambient.density * ambient.specific_internal_energy;
    ++sums.contributors[row];
  }
  return sums;
}

}  // namespace mpfd::coupler::remap
