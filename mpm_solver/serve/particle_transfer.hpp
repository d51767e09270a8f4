#pragma once
// Particle operations of protocol v1 (proto/README.md §6) on the MPM zone:
// InjectParticles, RemoveParticles (by id, or those outside a region) and
// ExportRegion of a PARTICLES region. Arrays per particle, in the layout of
// particles.proto: id U64 [n], position/velocity F64 [n, 3], mass, volume,
// internal_energy F64 [n], material U32 [n], stress F64 [n, 6] (Voigt xx,
// yy, zz, yz, xz, xy), burn_fraction F64 [n].

#include <cstdint>
#include <string>
#include <vector>

#include "cosim/message.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "mpm_solver/serve/zone_region.hpp"

namespace mpfd::mpm {

/// What the particle scans of a step need, kept by the zone between calls so
/// that they do not allocate once grown.
struct ParticleScratch {
  std::vector<std::size_t> members;  ///< the particles inside an exported region
  std::vector<std::uint8_t> flags;   ///< per particle: 1 to remove (outside the region, or named)
};

/// The arrays `group`/{id, position, velocity, mass, volume, internal_energy,
/// material[, stress]} of `message` as a batch. Throws
/// cosim::ProtocolError{MALFORMED} naming the operation, the group and the
/// array that is missing or has the wrong dtype or size.
[[nodiscard]] ParticleBatch read_particle_batch(const cosim::Message& message,
                                                const std::string& operation,
                                                const std::string& group);

/// Injects the particles of arrays `group`/{id, position, velocity, mass,
/// volume, internal_energy, material[, stress]}. Returns the count. Throws
/// cosim::ProtocolError{MALFORMED} naming the group and the array (missing, wrong
/// dtype or size) or the particle the solver refused.
std::uint64_t inject_particles(MpmSolver& solver, const cosim::v1::InjectParticles& op,
                               const cosim::Message& request);

/// Removes the particles listed in `group`/id (left_region empty) or every
/// particle outside the PARTICLES region `left_region`, and appends their
/// state as arrays of group `group` (id, position, velocity, mass, volume,
/// internal_energy, material, stress), unless op.discard (v1.2: the count
/// only; another solver owns them now). Returns the count. Throws
/// cosim::ProtocolError{MALFORMED} for an id array that is missing, not U64, or
/// names a particle the zone does not hold, UNKNOWN_REGION for left_region.
std::uint64_t remove_particles(MpmSolver& solver, const ZoneRegion* left_region,
                               const cosim::v1::RemoveParticles& op, const cosim::Message& request,
                               cosim::Message& reply, ParticleScratch& scratch);

/// Appends the asked quantities (none: the region's) of the particles inside
/// the region's box of cells, in particle order. Returns their count.
std::uint64_t export_particle_region(const MpmSolver& solver, const ZoneRegion& region,
                                     const cosim::v1::ExportRegion& request, cosim::Message& reply,
                                     ParticleScratch& scratch);

}  // namespace mpfd::mpm
