#pragma once
// What a 1D -> Cartesian remap knows of each material in each cell, as the
// sums the FDM's per-material start is fitted to (handoff/material_start.hpp)
// at spherical_to_fdm: per cell c and material r, over the shells k of
// material r that overlap c (spherical_to_cartesian.hpp, V_ck exact),
//   m_r = sum_k rho_k V_ck,  V_r = sum_k V_ck,  E_r = sum_k rho_k e_k V_ck,
// and the ambient fill of what the shells leave uncovered, (1 - covered) V_c of
// the ambient material at its density and energy.

#include "coupler/handoff/material_start.hpp"
#include "coupler/handoff/placeholder.hpp"
#include "coupler/remap/spherical_to_cartesian.hpp"

namespace mpfd::coupler::remap {

/// A material's share of a cell below which it is round-off, not a contributor: a
/// cell whose shells cover it to 1 - 1e-15 has no ambient fill, and a shell that
/// touches a cell by 1e-15 of its volume none of its material (the remap's
/// fields hold every bit of it; only the per-material start ignores it).
inline constexpr double kNegligibleFraction = 1e-12;

/// The sums of `f` (remapped on cells of volume `cell_volume` [m^3]) and the
/// fill, as rows of `materials` materials (the scene's count). Consumes `f`:
/// its per-material arrays become the sums' (the handoff's memory peak), and it
/// is left empty. Throws mpfd::Error if the profile or the ambient material is
/// not among them.
[[nodiscard]] handoff::MaterialSums shell_material_sums(CartesianFields&& f, double cell_volume,
                                                        const handoff::AmbientState& ambient,
                                                        int materials);

}  // namespace mpfd::coupler::remap
