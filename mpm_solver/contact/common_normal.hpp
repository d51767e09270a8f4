#pragma once
// The one normal shared by the bodies in contact at a node, T (2-23), (2-24).

#include <cstddef>
#include <optional>
#include <span>

#include "mpm_solver/contact/node_bodies.hpp"

namespace mpfd::mpm::contact {

/// The unit outward normal of body `normal_body` at the node, n^A = -n^B = n̂^A
/// of T (2-24), with n̂ from its mass gradient, T (2-23). The thesis takes A as
/// the stiffer body, or the one whose surface is convex; the caller names it.
/// If A's mass gradient vanishes (the node lies inside A), the other bodies'
/// gradients, summed and reversed, give the normal; nothing if that vanishes too.
template <int Dim>
[[nodiscard]] std::optional<Vec<Dim>> common_normal(std::span<const Vec<Dim>> mass_gradient,
                                                    std::size_t normal_body);

}  // namespace mpfd::mpm::contact
