#include "coupler/remap/shell_material_sums.hpp"

#include <string>
#include <utility>

#include "common/core/error.hpp"

namespace mpfd::coupler::remap {

handoff::MaterialSums shell_material_sums(CartesianFields&& f, double cell_volume,
                                          const handoff::AmbientState& ambient, int materials) {
  if (f.material_count > materials || ambient.material < 0 || ambient.material >= materials)
    throw Error("shell material sums: the profile holds " + std::to_string(f.material_count) +
                " materials and the ambient is material " + std::to_string(ambient.material) +
                "; the scene has " + std::to_string(materials));
  const std::size_t cells = f.covered_fraction.size();
  const auto to = static_cast<std::size_t>(materials);
  const auto from = static_cast<std::size_t>(f.material_count);
  handoff::MaterialSums sums(0, materials);
  if (from == to) {  // f's own arrays, taken over: no second copy at the handoff's peak
    sums.mass = std::move(f.material_mass);
    sums.volume = std::move(f.volume_fraction);
    sums.energy = std::move(f.material_internal_energy);
  } else {
    const std::size_t rows = cells * to;
    sums.mass.assign(rows, 0.0);
    sums.volume.assign(rows, 0.0);
    sums.energy.assign(rows, 0.0);
    for (std::size_t c = 0; c < cells; ++c)
      for (std::size_t r = 0; r < from; ++r) {
        sums.mass[c * to + r] = f.material_mass[c * from + r];
        sums.volume[c * to + r] = f.volume_fraction[c * from + r];
        sums.energy[c * to + r] = f.material_internal_energy[c * from + r];
      }
  }
  sums.contributors.assign(cells * to, 0);
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t r = 0; r < to; ++r) {
      const std::size_t row = c * to + r;
      const double theta = sums.volume[row];
      sums.volume[row] = theta * cell_volume;
      if (theta > kNegligibleFraction) {
        sums.contributors[row] = 1;
      } else {  // none, or the round-off of a shell's exact overlap
        sums.mass[row] = sums.volume[row] = sums.energy[row] = 0.0;
      }
    }
    const double rest = 1.0 - f.covered_fraction[c];
    if (!(rest > kNegligibleFraction)) continue;  // covered, to round-off
    const std::size_t row = c * to + static_cast<std::size_t>(ambient.material);
    sums.mass[row] += rest * cell_volume * ambient.density;
    sums.volume[row] += rest * cell_volume;
    sums.energy[row] += rest * cell_volume * ambient.density * ambient.specific_internal_energy;
    ++sums.contributors[row];
  }
  f = {};
  return sums;
}

}  // namespace mpfd::coupler::remap
