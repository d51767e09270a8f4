#pragma once
// ApplyRegion and ExportRegion of protocol v1 (proto/README.md §6) on the FDM
// state: arrays of group `region`, one per quantity, F64, [n] or [n, 3] in
// box C order (cell_region.hpp).

#include <cstdint>

#include "cosim/message.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "fdm_solver/serve/cell_region.hpp"

namespace mpfd::fdm {

/// Sets (MODE_SET) or adds to (MODE_ADD) the region's cells with every array
/// of group region.name in `request`, written through state_for_update. All
/// arrays are checked before any is written: each must be a writable quantity
/// the region declares, given once, F64, with cells x components values.
/// Throws cosim::ProtocolError{MALFORMED or UNKNOWN_REGION} naming region, quantity,
/// expected and got.
void apply_region(EulerSolver& solver, const CellRegion& region, cosim::v1::ApplyRegion::Mode mode,
                  const cosim::Message& request);

/// Appends one array per asked quantity (none asked: the region's) to `reply`,
/// each copied once from the state into its frame. Returns the cell count. An
/// export of a FACES region clears the solver's watched crossing (v1.1: each
/// export carries what crossed since the previous one).
/// Throws cosim::ProtocolError{UNKNOWN_REGION} for a quantity the region does not declare.
std::uint64_t export_region(EulerSolver& solver, const CellRegion& region,
                            const cosim::v1::ExportRegion& request, cosim::Message& reply);

}  // namespace mpfd::fdm
