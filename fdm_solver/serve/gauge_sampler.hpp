#pragma once
// SampleGauges of protocol v1 (proto/README.md §6) on the FDM state: each
// gauge reads the cell that holds it (as `fdm_solver run` records gauges).

#include <cstdint>

#include "cosim/message.hpp"
#include "fdm_solver/euler_solver.hpp"

namespace mpfd::fdm {

/// Appends one F64 [n_gauges] array per quantity, group request.group(), to
/// `reply`; returns n_gauges. Quantities: rho, E, pressure and the components
/// momentum_x, ..., velocity_z. `positions` holds d = 1, 2 or 3 coordinates
/// (x[, y[, z]]) per gauge; an axis left out must have one cell. Throws
/// cosim::ProtocolError{MALFORMED} naming the gauge, position or quantity.
std::uint64_t sample_gauges(const EulerSolver& solver, const cosim::v1::SampleGauges& request,
                            cosim::Message& reply);

}  // namespace mpfd::fdm
