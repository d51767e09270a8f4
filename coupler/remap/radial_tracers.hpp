#pragma once
// Tracers for the FDM after the 1D spherical -> 3D handoff (design §3.5 H1s
// step 4): the FDM needs material marks (T §3.2.2) besides the remapped
// conserved fields. tracers_per_axis^d tracers per cell at the sub-cell
// centres (where fdm_solver's seed_from_materials puts them), each of the
// material of the shell holding its distance from the centre; below r_0 the
// ambient material. The fraction of a cell's tracers of material r
// approximates the remap's exact volume fraction theta_r
// (spherical_to_cartesian.hpp) by the midpoint rule. When the outermost shell
// is of the ambient material (the 1D stage's air), only the cells that reach
// into the profile's ball (r < r_N) get tracers: the FDM gives a cell without
// tracers the material of the nearest cell holding some (fdm_solver's
// empty_cell_fill), which beyond the ball is that outer shell's; otherwise every
// cell gets them. Tracers in the air far from the products would only be carried: on
// the V4 far-field octant they took 63 % of the run.
// Geometry as the remap: 3D grids spherical about `centre`; 2D x-y grids
// cylindrical about the z axis through it.

#include "common/grid/uniform_grid.hpp"
#include "coupler/handoff/particle_fields.hpp"
#include "coupler/remap/radial_profile.hpp"

namespace mpfd::coupler::remap {

/// Throws mpfd::Error for a 1D grid, a 2D grid whose inactive axis is not z,
/// an inconsistent profile, ambient_material < 0 or tracers_per_axis < 1.
[[nodiscard]] handoff::TracerPoints radial_tracers(const grid::UniformGrid& grid,
                                                   const grid::Vec3& centre,
                                                   const RadialProfile& profile,
                                                   int ambient_material, int tracers_per_axis);

}  // namespace mpfd::coupler::remap
