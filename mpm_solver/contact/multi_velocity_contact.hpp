#pragma once
// Bardenhagen's multi-velocity-field contact with Coulomb friction at one grid
// node, T (2-22) ... (2-32). Each body is first advanced on its own, T (2-25);
// if the bodies approach, T (2-22), body A (the normal body) receives the
// contact force that gives both the common velocity, T (2-29), split along the
// common normal, T (2-30), (2-31), and limited by Coulomb friction, T (2-32):
//   stick    Δp^A = (m^A p̄^B - m^B p̄^A) / (m^A + m^B)        = Δt f^{A,c}
//   slide    Δp^A = Δp_nor + µ |Δp_nor| Δp_tan / |Δp_tan|   if |Δp_tan| > µ |Δp_nor|
// and B receives -Δp^A (T prints (2-29) with superscript b for both bodies;
// only f^{B,c} = -f^{A,c} conserves momentum, as in Bardenhagen et al. 2000).
// With three or more bodies, B is all the others taken together and shares
// -Δp^A in proportion to mass, which leaves their relative motion alone (the
// thesis treats two bodies). Not modelled: a gap check on particle positions.

#include <cstddef>
#include <span>

#include "mpm_solver/contact/node_bodies.hpp"

namespace mpfd::mpm::contact {

struct ContactLaw {
  double friction = 0;          ///< Coulomb coefficient µ of T (2-32), >= 0
  std::size_t normal_body = 0;  ///< body A of T (2-24) (< the node's body count): gives the normal
};

/// The momentum changes Δp^b = Δt f^{b,c,n} that resolve contact between the
/// bodies' given momenta (T (2-22), (2-24), (2-29) ... (2-32)); they sum to zero.
/// All zero, and false returned, if fewer than two bodies, no normal, or the
/// bodies do not approach. `change` has one entry per body.
template <int Dim>
bool contact_momentum_changes(const NodeBodies<Dim>& bodies, const ContactLaw& law,
                              std::span<Vec<Dim>> change);

/// The nodal momentum update with contact, T (2-25) ... (2-32): from each
/// body's momentum p^{b,n} (in `at_step_n`) and force f^{b,n} = f^int + f^ext
/// writes p^{b,n+1} and the contact force f^{b,c,n}, T (2-27); the velocity of
/// T (2-28) is p^{b,n+1} / m^{b,n}. Returns whether the bodies were in contact.
template <int Dim>
bool advance_momentum_with_contact(const NodeBodies<Dim>& at_step_n,
                                   std::span<const Vec<Dim>> force, double dt,
                                   const ContactLaw& law, std::span<Vec<Dim>> new_momentum,
                                   std::span<Vec<Dim>> contact_force);

}  // namespace mpfd::mpm::contact
