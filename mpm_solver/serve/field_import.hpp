#pragma once
// FieldChunk and FieldImportCommit of protocol v1.2 (proto/README.md §15 rules
// 3–5) on the MPM zone: the chunks of a transfer are assembled into whole
// fields; the commit adds them as particles of the zone's PARTICLES regions.

#include "cosim/message.hpp"
#include "mpm_solver/serve/served_zone.hpp"

namespace mpfd::mpm {

/// Adds a FieldChunk to the zone's import (a chunk of a new transfer_id
/// discards an unfinished one) and acknowledges it. Throws a non-fatal
/// cosim::ProtocolError{MALFORMED} naming the field on a gap, overlap or
/// change of shape (FieldAssembly::add); the import is then dropped.
[[nodiscard]] cosim::v1::FieldChunkAck receive_field_chunk(ServedZone& zone,
                                                           const cosim::Message& chunk);

/// Commits the assembled import atomically: every field is
/// "<PARTICLES region>/<quantity>" with the arrays of InjectParticles (id,
/// position, velocity, mass, volume, internal_energy, material[, stress]),
/// every particle inside its region's box; the particles of all regions are
/// added in one MpmSolver::inject_particles. The clock becomes the commit's
/// envelope sim_time (§15 rule 4). Returns FieldImportDone with the stable dt
/// and the totals of the added particles as the solver holds them: mass,
/// momentum x, y, z, internal + kinetic energy (rule 5). Every commit ends the
/// import: a refused one is a non-fatal cosim::ProtocolError with the zone
/// unchanged, and the coupler sends the transfer again whole. MALFORMED: no
/// complete import of that transfer, tracers set, a missing or bad array, a
/// particle outside its box or refused by the solver; UNKNOWN_REGION: a
/// region or quantity not declared; UNEXPECTED: a NODES region (export only).
[[nodiscard]] cosim::v1::FieldImportDone commit_field_import(ServedZone& zone,
                                                             const cosim::Message& commit);

}  // namespace mpfd::mpm
