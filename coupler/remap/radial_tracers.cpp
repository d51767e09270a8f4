#include "coupler/remap/radial_tracers.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/core/error.hpp"
#include "coupler/handoff/sub_cell_centres.hpp"

namespace mpfd::coupler::remap {

handoff::TracerPoints radial_tracers(const grid::UniformGrid& grid, const grid::Vec3& centre,
                                     const RadialProfile& profile, int ambient_material,
                                     int tracers_per_axis) {
  const bool spherical = grid.dimension() == 3;
  if (!spherical && !(grid.dimension() == 2 && grid.is_active(0) && grid.is_active(1)))
    throw Error(
        "radial_tracers: the grid must be 3D (spherical profile) or 2D in x and y "
        "(cylindrical profile), got " +
        std::to_string(grid.dimension()) + "D");
  check_profile(profile);
  if (ambient_material < 0)
    throw Error("radial_tracers: ambient material must be >= 0, got " +
                std::to_string(ambient_material));
  if (tracers_per_axis < 1)
    throw Error("radial_tracers: tracers per cell and axis must be >= 1, got " +
                std::to_string(tracers_per_axis));
  const int axes = spherical ? 3 : 2;
  const auto material_at = [&](const grid::Vec3& x) {
    double r2 = 0.0;
    for (int a = 0; a < axes; ++a) r2 += (x[a] - centre[a]) * (x[a] - centre[a]);
    const double r = std::sqrt(r2);
    if (r < profile.edges.front() || r >= profile.edges.back()) return ambient_material;
    // The shell k with r_k <= r < r_{k+1}.
    const auto above = std::upper_bound(profile.edges.begin(), profile.edges.end(), r);
    return profile.material[static_cast<std::size_t>(above - profile.edges.begin() - 1)];
  };

  // Whether some point of the cell lies within the profile's outer radius. The
  // fill gives an empty cell its nearest seeded cell's material: beyond the ball
  // that is the outer shell's, so cells there go unseeded only if it is ambient.
  const double outer = profile.material.back() == ambient_material
                           ? profile.edges.back()
                           : std::numeric_limits<double>::infinity();
  const auto reaches_profile = [&](const grid::Index3& cell) {
    double r2 = 0.0;
    for (int a = 0; a < axes; ++a) {
      const double lo = grid.origin()[a] + cell[a] * grid.spacing()[a];
      const double nearest = std::clamp(centre[a], lo, lo + grid.spacing()[a]);
      r2 += (nearest - centre[a]) * (nearest - centre[a]);
    }
    return r2 < outer * outer;
  };

  std::vector<std::size_t> seeded;
  for (std::size_t c = 0; c < grid.cell_count(); ++c)
    if (reaches_profile(grid.cell_of_index(c))) seeded.push_back(c);
  handoff::TracerPoints tracers;
  const std::size_t count = seeded.size() * handoff::sub_cell_count(grid, tracers_per_axis);
  for (auto& x : tracers.position) x.reserve(count);
  tracers.material.reserve(count);
  for (const std::size_t c : seeded)
    handoff::for_each_sub_cell_centre(grid, grid.cell_of_index(c), tracers_per_axis,
                                      [&](const grid::Vec3& x) {
                                        for (int a = 0; a < 3; ++a)
                                          tracers.position[a].push_back(x[a]);
                                        tracers.material.push_back(material_at(x));
                                      });
  return tracers;
}

}  // namespace mpfd::coupler::remap
