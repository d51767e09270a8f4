#pragma once
// ApplyRegion and ExportRegion of protocol v1 (proto/README.md §6) on a NODES
// region of the MPM zone: arrays of group `region`, F64, [n] or [n, 3] in box
// C order (zone_region.hpp).

#include <cstdint>

#include "cosim/message.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "mpm_solver/serve/zone_region.hpp"

namespace mpfd::mpm {

/// Queues (MpmSolver::queue_node_load) every array of group region.name:
/// mass [n] kg, momentum [n, 3] kg m/s, internal_force [n, 3] N; SET
/// replaces the mapped value at the next advance, ADD adds to it (T (4-7)...
/// (4-9)). All arrays are checked before any is queued. Throws
/// cosim::ProtocolError{MALFORMED or UNKNOWN_REGION} naming region, quantity,
/// expected and got.
void apply_node_region(MpmSolver& solver, const ZoneRegion& region,
                       cosim::v1::ApplyRegion::Mode mode, const cosim::Message& request);

/// Maps the particles to the region's nodes first, then appends one array per
/// asked quantity (none asked: the region's): mass, momentum of each node, and
/// internal_energy of each cell of ZoneRegion::cell_count, the nodal
/// sum_p N_Ip m_p e_p at the cell centre (T (4-3) with the support of (4-1))
/// [J]. With `next_step_map_seconds` the map is the next advance's own
/// (MpmSolver::map_next_step; its wall time is added there, and the advance
/// reports it as its own) unless another box holds that map; otherwise (or
/// null: a field export, which changes nothing) the particles that reach the
/// box are mapped into `map` (the zone's scratch). Returns the node count.
std::uint64_t export_node_region(MpmSolver& solver, const ZoneRegion& region,
                                 const cosim::v1::ExportRegion& request, NodeBoxMap& map,
                                 double* next_step_map_seconds, cosim::Message& reply);

}  // namespace mpfd::mpm
