// A block on an incline, reduced to one grid node shared by the block (body 0)
// and the incline (body 1): the classic check of frictional contact. The
// incline is held fixed (its nodal momentum is reset each step, as a rigid
// support would be) and is a billion times heavier, so the block's acceleration
// along the slope must be g (sin θ - µ cos θ) while it slides and zero while
// friction holds it.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "mpm_solver/contact/multi_velocity_contact.hpp"

namespace mpfd::mpm::contact {
namespace {

struct InclineRun {
  double speed_down_slope;  ///< block velocity along the slope at the end, m/s
  double speed_normal;      ///< block velocity along the incline's normal, m/s
};

InclineRun slide(double theta, double mu, int steps, double dt) {
  const double g = 9.81;
  const Vec<2> down_slope(std::cos(theta), -std::sin(theta));
  const Vec<2> normal(std::sin(theta), std::cos(theta));  // out of the incline, into the block
  const std::array<double, 2> mass{1.0, 1e9};
  const std::array<Vec<2>, 2> gradient{-normal, 3.0 * normal};
  const std::array<Vec<2>, 2> force{mass[0] * Vec<2>(0, -g), Vec<2>::Zero()};
  std::array<Vec<2>, 2> momentum{Vec<2>::Zero(), Vec<2>::Zero()};
  std::array<Vec<2>, 2> new_momentum{}, contact_force{};
  const ContactLaw law{mu, 1};  // the incline, the stiffer body, gives the normal (T (2-24))
  for (int step = 0; step < steps; ++step) {
    const NodeBodies<2> node{mass, momentum, gradient};
    advance_momentum_with_contact<2>(node, force, dt, law, new_momentum, contact_force);
    momentum = {new_momentum[0], Vec<2>::Zero()};
  }
  const Vec<2> v = momentum[0] / mass[0];
  return {v.dot(down_slope), v.dot(normal)};
}

TEST(InclineContact, SlidingBlockAcceleratesAtGTimesSinMinusMuCos) {
  const double theta = std::numbers::pi / 6, mu = 0.2, dt = 1e-4, g = 9.81;
  const int steps = 10000;
  const InclineRun run = slide(theta, mu, steps, dt);
  const double expected = g * (std::sin(theta) - mu * std::cos(theta)) * steps * dt;
  // Once the block's small steady approach into the 1e9-times heavier incline is
  // set, the normal impulse balances g cos θ exactly: measured 2e-14 relative.
  EXPECT_NEAR(run.speed_down_slope, expected, 1e-10 * expected);
  // The incline takes 1e-9 of the block's approach each step: |v_n| ~ 1e-12 m/s.
  EXPECT_NEAR(run.speed_normal, 0, 1e-11);
}

TEST(InclineContact, FrictionlessBlockAcceleratesAtGSinTheta) {
  const double theta = 0.4, dt = 1e-4, g = 9.81;
  const int steps = 5000;
  const InclineRun run = slide(theta, 0.0, steps, dt);
  const double expected = g * std::sin(theta) * steps * dt;
  EXPECT_NEAR(run.speed_down_slope, expected, 1e-10 * expected);
}

TEST(InclineContact, FrictionAboveTanThetaHoldsTheBlock) {
  const double theta = std::numbers::pi / 6;  // tan θ = 0.577
  const InclineRun run = slide(theta, 0.6, 10000, 1e-4);
  EXPECT_NEAR(run.speed_down_slope, 0, 1e-11);  // the incline's 1e-9 share, as above
  EXPECT_NEAR(run.speed_normal, 0, 1e-11);
}

}  // namespace
}  // namespace mpfd::mpm::contact
