#pragma once
// The import side of whole-field transfers (proto/README.md §15 rules 3-5,
// v1.2): FieldChunks are collected in the zone's pending import, each
// acknowledged; FieldImportCommit checks the whole import, then hands it to
// EulerSolver::import_state at once: the CELLS region (the whole grid) with
// rho, momentum and E sets every cell, a TRACERS region's position and
// material replace the tracers inside its box (T (3-3)-(3-8): MPM particles
// become the FDM's tracers). With capability material_import the CELLS region
// may also carry volume_fraction, material_density and material_energy
// (F64 [n, materials], all three): each material's own start in the mixed
// cells (tracker_import.hpp); without them every material starts from its
// cell's state. The clock becomes the commit's sim_time.

#include "cosim/message.hpp"
#include "fdm_solver/serve/served_zone.hpp"

namespace mpfd::fdm {

/// Adds a FieldChunk to the pending import (a chunk of a new transfer_id
/// discards an unfinished one) and returns its FieldChunkAck. Throws
/// cosim::ProtocolError{MALFORMED}, non-fatal, on a chunk out of order; the
/// pending import is then dropped.
[[nodiscard]] cosim::Message add_import_chunk(ServedZone& zone, const cosim::Message& chunk);

/// Applies the pending import and returns FieldImportDone {stable_dt, totals
/// [mass, px, py, pz, E] of the imported cells}. Throws cosim::ProtocolError
/// (MALFORMED or UNKNOWN_REGION, non-fatal) naming the field and the rule, with
/// the zone untouched, when the transfer is unknown or incomplete, a field's
/// region is not declared, the CELLS fields do not cover the whole grid with
/// rho, momentum and E or carry only some of the three per-material start
/// fields, a value is not finite or a density not positive, a
/// tracer lies outside its region's box or has a material the scene lacks, or
/// `tracers` disagrees with the fields. The pending import is consumed.
[[nodiscard]] cosim::Message commit_import(ServedZone& zone, const cosim::Message& commit);

}  // namespace mpfd::fdm
