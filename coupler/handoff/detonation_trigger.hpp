#pragma once
// When phase 1 ends (T §3.2.1): the program burn of T (3-1), (3-2) lights
// each explosive particle at t_L = distance / D and ramps its reaction
// fraction F; the MPM -> FDM handoff fires once every explosive particle has
// F >= 1.

#include <span>

namespace mpfd::coupler::handoff {

/// T (3-2): F = (t - t_L) D / (1.5 h) for t >= t_L, 0 before, capped at 1
/// (T: "F exceeds 1 after a few steps and then stays 1"). Throws
/// mpfd::Error unless D > 0 and h > 0.
[[nodiscard]] double reaction_fraction(double time, double ignition_time,
                                       double detonation_velocity, double length);

/// True when every particle whose material is in `explosive_materials` has
/// F >= 1 (vacuously true without explosive particles). Throws mpfd::Error
/// if the two per-particle arrays differ in size.
[[nodiscard]] bool detonation_complete(std::span<const double> reaction_fraction,
                                       std::span<const int> material,
                                       std::span<const int> explosive_materials);

}  // namespace mpfd::coupler::handoff
