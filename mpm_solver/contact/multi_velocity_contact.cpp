#include "mpm_solver/contact/multi_velocity_contact.hpp"

#include "mpm_solver/contact/common_normal.hpp"

namespace mpfd::mpm::contact {

template <int Dim>
bool contact_momentum_changes(const NodeBodies<Dim>& bodies, const ContactLaw& law,
                              std::span<Vec<Dim>> change) {
  for (auto& c : change) c.setZero();
  if (bodies.count() < 2) return false;
  const std::size_t a = law.normal_body;
  const double mass_a = bodies.mass[a];
  const Vec<Dim>& momentum_a = bodies.momentum[a];
  double mass_b = 0;
  Vec<Dim> momentum_b = Vec<Dim>::Zero();
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    if (b == a) continue;
    mass_b += bodies.mass[b];
    momentum_b += bodies.momentum[b];
  }
  if (!(mass_a > 0 && mass_b > 0)) return false;
  const auto normal = common_normal<Dim>(bodies.mass_gradient, a);
  if (!normal) return false;
  const Vec<Dim> relative_velocity = momentum_a / mass_a - momentum_b / mass_b;
  if (relative_velocity.dot(*normal) <= 0) return false;  // only approaching bodies, T (2-22)

  // T (2-29) times Δt: A's share of the common velocity minus its own momentum.
  const Vec<Dim> stick = (mass_a * momentum_b - mass_b * momentum_a) / (mass_a + mass_b);
  const Vec<Dim> normal_part = stick.dot(*normal) * *normal;  // T (2-30)
  const Vec<Dim> tangential_part = stick - normal_part;       // T (2-31)
  const double friction_limit = law.friction * normal_part.norm();
  const double tangential = tangential_part.norm();
  // Stick while the tangential force is within µ |f_nor|, else slide, T (2-32).
  const Vec<Dim> change_a =
      tangential <= friction_limit
          ? stick
          : Vec<Dim>(normal_part + (friction_limit / tangential) * tangential_part);
  change[a] = change_a;
  for (std::size_t b = 0; b < bodies.count(); ++b) {
    if (b != a) change[b] = -(bodies.mass[b] / mass_b) * change_a;
  }
  return true;
}

template <int Dim>
bool advance_momentum_with_contact(const NodeBodies<Dim>& at_step_n,
                                   std::span<const Vec<Dim>> force, double dt,
                                   const ContactLaw& law, std::span<Vec<Dim>> new_momentum,
                                   std::span<Vec<Dim>> contact_force) {
  for (std::size_t b = 0; b < at_step_n.count(); ++b) {
    new_momentum[b] = at_step_n.momentum[b] + dt * force[b];  // trial momentum, T (2-25)
  }
  const NodeBodies<Dim> trial{at_step_n.mass, new_momentum, at_step_n.mass_gradient};
  const bool in_contact = contact_momentum_changes<Dim>(trial, law, contact_force);
  for (std::size_t b = 0; b < at_step_n.count(); ++b) {
    new_momentum[b] += contact_force[b];  // T (2-27)
    contact_force[b] /= dt;
  }
  return in_contact;
}

#define MPFD_INSTANTIATE_CONTACT(Dim)                                                    \
  template bool contact_momentum_changes<Dim>(const NodeBodies<Dim>&, const ContactLaw&, \
                                              std::span<Vec<Dim>>);                      \
  template bool advance_momentum_with_contact<Dim>(                                      \
      const NodeBodies<Dim>&, std::span<const Vec<Dim>>, double, const ContactLaw&,      \
      std::span<Vec<Dim>>, std::span<Vec<Dim>>);
MPFD_INSTANTIATE_CONTACT(1)
MPFD_INSTANTIATE_CONTACT(2)
MPFD_INSTANTIATE_CONTACT(3)
#undef MPFD_INSTANTIATE_CONTACT

}  // namespace mpfd::mpm::contact
