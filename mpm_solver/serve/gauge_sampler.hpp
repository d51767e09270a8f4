#pragma once
// SampleGauges of protocol v1 (proto/README.md §6) on the MPM zone: each
// gauge reads the particle nearest to it, as `mpm_solver run` records gauges,
// or, when the zone's scene gives a gauge of that name follow: material, the
// particle bound to it at Setup (followed_gauges.hpp), wherever it is now.

#include <cstdint>

#include "cosim/message.hpp"
#include "mpm_solver/followed_gauges.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {

/// Appends one F64 [n_gauges] array per quantity (density, pressure,
/// velocity_x, velocity_y, velocity_z, specific_internal_energy, position_x,
/// position_y, position_z [m], and mises_stress [Pa], the von Mises stress of
/// the particle's deviator; NaN for a followed particle that has left), group
/// request.group(), to `reply`; returns n_gauges. `positions` holds three
/// coordinates per gauge. Throws cosim::ProtocolError{MALFORMED} naming the
/// quantity or the position count, or when the zone holds no particle.
std::uint64_t sample_gauges(const MpmSolver& solver, FollowedGauges& followed,
                            const cosim::v1::SampleGauges& request, cosim::Message& reply);

}  // namespace mpfd::mpm
