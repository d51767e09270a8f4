#include "mpm_solver/contact/multi_velocity_contact.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace mpfd::mpm::contact {
namespace {

// Round-off tolerance, relative to the O(1..10) momenta used here.
constexpr double kContactTol = 1e-13;

template <int Dim>
struct Node {
  std::vector<double> mass;
  std::vector<Vec<Dim>> momentum;
  std::vector<Vec<Dim>> gradient;

  [[nodiscard]] NodeBodies<Dim> view() const { return {mass, momentum, gradient}; }
  [[nodiscard]] Vec<Dim> velocity(std::size_t b) const { return momentum[b] / mass[b]; }
  [[nodiscard]] Vec<Dim> total() const {
    Vec<Dim> sum = Vec<Dim>::Zero();
    for (const auto& p : momentum) sum += p;
    return sum;
  }
  void apply(const std::vector<Vec<Dim>>& change) {
    for (std::size_t b = 0; b < momentum.size(); ++b) momentum[b] += change[b];
  }
};

// Body A (mass 2.5) runs into body B (mass 4) across the normal (1, 2, 2)/3 of A.
Node<3> oblique_approach() {
  const Vec<3> surface(1, 2, 2);
  return {{2.5, 4.0},
          {2.5 * Vec<3>(3, -1, 2), 4.0 * Vec<3>(-1, 0.5, -0.3)},
          {0.7 * surface, -0.4 * surface}};
}

Vec<3> tangential(const Vec<3>& v, const Vec<3>& n) {
  return v - v.dot(n) * n;
}

TEST(MultiVelocityContact, ApproachingBodiesGetOneNormalVelocityAndKeepTotalMomentum) {
  Node<3> node = oblique_approach();
  const Vec<3> n = Vec<3>(1, 2, 2) / 3;
  const Vec<3> total_before = node.total();
  ASSERT_GT((node.velocity(0) - node.velocity(1)).dot(n), 1);
  std::vector<Vec<3>> change(2);
  ASSERT_TRUE(contact_momentum_changes<3>(node.view(), {0.25, 0}, change));
  node.apply(change);
  EXPECT_NEAR((node.velocity(0) - node.velocity(1)).dot(n), 0, kContactTol);
  EXPECT_NEAR((node.total() - total_before).norm(), 0, 1e-15 * total_before.norm() * 4);
}

TEST(MultiVelocityContact, SeparatingBodiesAreLeftAlone) {
  Node<3> node = oblique_approach();
  for (auto& p : node.momentum) p = -p;
  const std::vector<Vec<3>> force{Vec<3>(1, 2, 3), Vec<3>(-4, 5, -6)};
  std::vector<Vec<3>> new_momentum(2), contact_force(2);
  const double dt = 1e-3;
  EXPECT_FALSE(advance_momentum_with_contact<3>(node.view(), force, dt, {0.3, 0}, new_momentum,
                                                contact_force));
  for (std::size_t b = 0; b < 2; ++b) {
    EXPECT_EQ(new_momentum[b], Vec<3>(node.momentum[b] + dt * force[b]));  // T (2-25) only
    EXPECT_EQ(contact_force[b], Vec<3>::Zero());
  }
}

TEST(MultiVelocityContact, SlidingTangentialImpulseIsMuTimesNormalImpulse) {
  Node<3> node = oblique_approach();
  const Vec<3> n = Vec<3>(1, 2, 2) / 3;
  const double mu = 0.1;
  const Vec<3> slip_before = tangential(node.velocity(0) - node.velocity(1), n);
  std::vector<Vec<3>> change(2);
  ASSERT_TRUE(contact_momentum_changes<3>(node.view(), {mu, 0}, change));
  const double normal_impulse = std::abs(change[0].dot(n));
  EXPECT_NEAR(tangential(change[0], n).norm(), mu * normal_impulse, kContactTol * normal_impulse);
  node.apply(change);
  // Friction slows the slip but never reverses it.
  const Vec<3> slip_after = tangential(node.velocity(0) - node.velocity(1), n);
  EXPECT_LT(slip_after.norm(), slip_before.norm());
  EXPECT_NEAR(slip_after.normalized().dot(slip_before.normalized()), 1, kContactTol);
}

TEST(MultiVelocityContact, StickWithinTheFrictionLimitGivesOneCommonVelocity) {
  Node<3> node = oblique_approach();
  const Vec<3> centre_of_mass = node.total() / (node.mass[0] + node.mass[1]);
  std::vector<Vec<3>> change(2);
  ASSERT_TRUE(contact_momentum_changes<3>(node.view(), {10.0, 0}, change));
  node.apply(change);
  EXPECT_NEAR((node.velocity(0) - centre_of_mass).norm(), 0, kContactTol);
  EXPECT_NEAR((node.velocity(1) - centre_of_mass).norm(), 0, kContactTol);
}

TEST(MultiVelocityContact, FrictionlessContactKeepsEachTangentialVelocity) {
  Node<3> node = oblique_approach();
  const Vec<3> n = Vec<3>(1, 2, 2) / 3;
  const Vec<3> tangential_a = tangential(node.velocity(0), n);
  const Vec<3> tangential_b = tangential(node.velocity(1), n);
  std::vector<Vec<3>> change(2);
  ASSERT_TRUE(contact_momentum_changes<3>(node.view(), {0.0, 0}, change));
  node.apply(change);
  EXPECT_NEAR((tangential(node.velocity(0), n) - tangential_a).norm(), 0, kContactTol);
  EXPECT_NEAR((tangential(node.velocity(1), n) - tangential_b).norm(), 0, kContactTol);
}

// T (2-25) ... (2-32) written out for two bodies as printed, with f^{B,c} = -f^{A,c}.
struct ThesisStep {
  Vec<2> momentum_a, momentum_b, force_a;
};

ThesisStep thesis_two_body_step(double ma, double mb, const Vec<2>& pa, const Vec<2>& pb,
                                const Vec<2>& fa, const Vec<2>& fb, const Vec<2>& na, double dt,
                                double mu) {
  const Vec<2> trial_a = pa + dt * fa, trial_b = pb + dt * fb;            // (2-25)
  const Vec<2> va = pa / ma + dt * fa / ma, vb = pb / mb + dt * fb / mb;  // (2-26)
  if ((va - vb).dot(na) <= 0) return {trial_a, trial_b, Vec<2>::Zero()};  // (2-22)
  Vec<2> f = (ma * trial_b - mb * trial_a) / ((ma + mb) * dt);            // (2-29)
  const Vec<2> f_nor = f.dot(na) * na;                                    // (2-30)
  const Vec<2> f_tan = f - f_nor;                                         // (2-31)
  if (f_tan.norm() >= mu * f_nor.norm()) {
    f = f_nor + mu * f_nor.norm() * f_tan / f_tan.norm();  // (2-32)
  }
  return {trial_a + dt * f, trial_b - dt * f, f};  // (2-27)
}

TEST(MultiVelocityContact, MomentumUpdateMatchesTheThesisFormulasForTwoBodies) {
  const double dt = 2e-4;
  const Vec<2> n(0.6, -0.8);
  // Relative slip/approach 0.29: mu 0 and 0.2 slide, 0.5 and 5 stick.
  const Node<2> node{{1.5, 0.7}, {Vec<2>(4, -2), Vec<2>(-2, 2)}, {2 * n, -n}};
  const std::vector<Vec<2>> force{Vec<2>(300, 100), Vec<2>(-50, 20)};
  for (const double mu : {0.0, 0.2, 0.5, 5.0}) {
    std::vector<Vec<2>> new_momentum(2), contact_force(2);
    EXPECT_TRUE(advance_momentum_with_contact<2>(node.view(), force, dt, {mu, 0}, new_momentum,
                                                 contact_force));
    const ThesisStep expected =
        thesis_two_body_step(node.mass[0], node.mass[1], node.momentum[0], node.momentum[1],
                             force[0], force[1], n, dt, mu);
    EXPECT_NEAR((new_momentum[0] - expected.momentum_a).norm(), 0, kContactTol) << "mu " << mu;
    EXPECT_NEAR((new_momentum[1] - expected.momentum_b).norm(), 0, kContactTol) << "mu " << mu;
    EXPECT_NEAR((contact_force[0] - expected.force_a).norm(), 0, kContactTol / dt) << "mu " << mu;
    EXPECT_NEAR((contact_force[1] + expected.force_a).norm(), 0, kContactTol / dt) << "mu " << mu;
  }
}

TEST(MultiVelocityContact, ThreeBodiesMeetTheNormalBodyAsOneAndKeepTheirRelativeMotion) {
  const Vec<2> n(0, 1);
  Node<2> node{{3.0, 1.0, 2.0},
               {3.0 * Vec<2>(0.5, 2), 1.0 * Vec<2>(1, 0.5), 2.0 * Vec<2>(-2, 1)},
               {n, -0.3 * n, -0.5 * n}};
  const Vec<2> total_before = node.total();
  const Vec<2> relative_before = node.velocity(1) - node.velocity(2);
  std::vector<Vec<2>> change(3);
  ASSERT_TRUE(contact_momentum_changes<2>(node.view(), {0.3, 0}, change));
  node.apply(change);
  EXPECT_NEAR((node.total() - total_before).norm(), 0, kContactTol);
  EXPECT_NEAR((node.velocity(1) - node.velocity(2) - relative_before).norm(), 0, kContactTol);
  const Vec<2> others = (node.momentum[1] + node.momentum[2]) / 3.0;
  EXPECT_NEAR((node.velocity(0) - others).dot(n), 0, kContactTol);
}

TEST(MultiVelocityContact, OneBodyOrAMasslessNormalBodyIsNoContact) {
  const Node<2> alone{{1.0}, {Vec<2>(1, 1)}, {Vec<2>(1, 0)}};
  std::vector<Vec<2>> change(1, Vec<2>(7, 7));
  EXPECT_FALSE(contact_momentum_changes<2>(alone.view(), {0.3, 0}, change));
  EXPECT_EQ(change[0], Vec<2>::Zero());
  const Node<2> massless{
      {0.0, 1.0}, {Vec<2>::Zero(), Vec<2>(-1, 0)}, {Vec<2>(1, 0), Vec<2>(-1, 0)}};
  std::vector<Vec<2>> changes(2);
  EXPECT_FALSE(contact_momentum_changes<2>(massless.view(), {0.3, 0}, changes));
}

}  // namespace
}  // namespace mpfd::mpm::contact
