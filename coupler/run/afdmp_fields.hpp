#pragma once
// The AFDMP handoffs' whole fields as they travel (proto/README.md §15) and as
// the handoff kernels hold them (coupler/handoff): particles from an MPM
// PARTICLES export, cells and tracers for an FDM import, the FDM's phase-2
// end state from its export, and particles for an MPM import. Cells travel in
// their box's C order (k fastest), vectors as [n, 3], materials as U32.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "common/grid/uniform_grid.hpp"
#include "cosim/message.hpp"
#include "coupler/handoff/fdm_to_mpm.hpp"
#include "coupler/handoff/material_start.hpp"
#include "coupler/handoff/particle_fields.hpp"

namespace mpfd::coupler {

/// Fields "<region>/<q>" for each quantity q, in order (field_transfer's names).
[[nodiscard]] std::vector<std::string> field_names(std::string_view region,
                                                   std::initializer_list<const char*> quantities);

/// Particles of an MPM export: position, velocity [n, 3], mass, internal_energy
/// [J], material and, if the export has it, volume [m^3] (else the volumes stay
/// 0) of `region`. Throws mpfd::Error naming a missing or inconsistent array.
[[nodiscard]] handoff::ParticleSet particles_from_wire(const cosim::Message& fields,
                                                       std::string_view region);

/// The cells of the whole grid `grid` (grid order) as rho, momentum [n, 3] and E
/// of `region` (wire order).
void add_cells_to_wire(const grid::UniformGrid& grid, const handoff::ConservedView& cells,
                       std::string_view region, cosim::Message& out);

/// Each material's start (material_start.hpp) of the whole grid `grid` as
/// volume_fraction, material_density and material_energy [n, materials] of
/// `region` (wire order).
void add_material_start_to_wire(const grid::UniformGrid& grid, const handoff::MaterialStart& start,
                                std::string_view region, cosim::Message& out);

/// Tracers as position [n, 3] and material of `region`.
void add_tracers_to_wire(const handoff::TracerView& tracers, std::string_view region,
                         cosim::Message& out);

/// Particles for an MPM import (arrays of InjectParticles): id from `first_id`
/// upward, position, velocity, mass, volume, internal_energy, material and the
/// stress -p I (T (3-17)) in Voigt order.
void add_particles_to_wire(const handoff::ParticleSet& particles, std::uint64_t first_id,
                           std::string_view region, cosim::Message& out);

/// The FDM's end of phase 2 in grid order of `grid` (the fluid box's grid),
/// read from an export of `cell_region` (rho, momentum, E, pressure,
/// cell_material, volume_fraction, material_density, material_energy) and
/// `tracer_region` (position, material). Owns its arrays; view() feeds fdm_to_mpm.
class FdmEndFields {
 public:
  FdmEndFields(const grid::UniformGrid& grid, const cosim::Message& fields,
               std::string_view cell_region, std::string_view tracer_region);
  [[nodiscard]] handoff::FdmEnd view() const;
  [[nodiscard]] const handoff::ConservedCells& cells() const { return cells_; }

 private:
  handoff::ConservedCells cells_;
  std::vector<double> pressure_;
  std::vector<int> cell_material_;
  int material_count_ = 0;
  std::vector<double> volume_fraction_, material_density_, material_energy_;
  handoff::TracerPoints tracers_;
};

}  // namespace mpfd::coupler
