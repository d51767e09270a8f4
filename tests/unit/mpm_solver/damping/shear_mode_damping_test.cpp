#include "mpm_solver/damping/shear_mode_damping.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <random>

namespace mpfd::mpm::damping {
namespace {

// Round-off tolerance for forces of O(alpha * |v|) with |v| = O(1).
constexpr double kTol = 1e-13;
constexpr double kAlpha = 1.7;
constexpr double kCellSize = 0.01;

// Table 2.1: (ξ, η, ζ) of the thesis's nodes 1..8, counter-clockwise per face.
constexpr std::array<std::array<int, 3>, 8> kThesisNodes{{{-1, -1, -1},
                                                          {1, -1, -1},
                                                          {1, 1, -1},
                                                          {-1, 1, -1},
                                                          {-1, -1, 1},
                                                          {1, -1, 1},
                                                          {1, 1, 1},
                                                          {-1, 1, 1}}};

// The grid's (x fastest) number of the thesis's node t.
int grid_node(int t) {
  const auto& c = kThesisNodes[t];
  return (c[0] > 0 ? 1 : 0) + (c[1] > 0 ? 2 : 0) + (c[2] > 0 ? 4 : 0);
}

// A thesis mode vector, printed in Table 2.1's node order, in the grid's order.
std::array<double, 8> in_grid_order(const std::array<double, 8>& thesis_order) {
  std::array<double, 8> grid{};
  for (int t = 0; t < 8; ++t) grid[grid_node(t)] = thesis_order[t];
  return grid;
}

template <int Dim>
Vec<Dim> node_position(int node, const Vec<Dim>& centre) {
  Vec<Dim> x = centre;
  for (int k = 0; k < Dim; ++k) x(k) += 0.5 * kCellSize * natural_coordinate(node, k);
  return x;
}

template <int Dim>
double largest_force(const CellVectors<Dim>& force) {
  double largest = 0;
  for (const auto& f : force) largest = std::max(largest, f.norm());
  return largest;
}

template <int Dim>
double power(const CellVectors<Dim>& force, const CellVectors<Dim>& velocity) {
  double p = 0;
  for (int node = 0; node < kCellNodes<Dim>; ++node) p += force[node].dot(velocity[node]);
  return p;
}

CellVectors<3> random_velocities(std::mt19937& generator) {
  std::uniform_real_distribution<double> uniform(-1, 1);
  CellVectors<3> v;
  for (auto& node : v) node = Vec<3>(uniform(generator), uniform(generator), uniform(generator));
  return v;
}

TEST(ShearModeDamping, ModeVectorsAreTheThesisTableInGridOrder) {
  // T (2-39), (2-40) as printed; (2-41) lost its eighth entry, restored from Table 2.1.
  const std::array<std::array<double, 8>, 3> lambda{
      {{-1, 1, 1, -1, -1, 1, 1, -1}, {-1, -1, 1, 1, -1, -1, 1, 1}, {-1, -1, -1, -1, 1, 1, 1, 1}}};
  for (int k = 0; k < 3; ++k) {
    const auto grid = in_grid_order(lambda[k]);
    for (int node = 0; node < 8; ++node) EXPECT_EQ(natural_coordinate(node, k), grid[node]);
  }
}

TEST(ShearModeDamping, RigidTranslationAndRotationGetNoForce) {
  const Vec<3> centre(0.3, -1.2, 2.0), omega(40, -25, 70), drift(3, -2, 1);
  CellVectors<3> v;
  for (int node = 0; node < 8; ++node)
    v[node] = drift + omega.cross(node_position<3>(node, centre));
  EXPECT_LT(largest_force<3>(shear_damping_forces<3>(v, kAlpha)), kTol);

  CellVectors<2> v2;
  const Vec<2> centre2(5, 7);
  for (int node = 0; node < 4; ++node) {
    const Vec<2> x = node_position<2>(node, centre2);
    v2[node] = Vec<2>(1, -4) + 60 * Vec<2>(-x(1), x(0));
  }
  EXPECT_LT(largest_force<2>(shear_damping_forces<2>(v2, kAlpha)), 100 * kTol);  // |v| ~ 400
}

TEST(ShearModeDamping, CompressionAndHourglassModesGetNoForce) {
  // Normal strain rates (k = i) are the EOS's business, not shear.
  CellVectors<3> v;
  for (int node = 0; node < 8; ++node) {
    v[node] = Eigen::Vector3d(-3, 2, 5).cwiseProduct(node_position<3>(node, Vec<3>(1, 1, 1)));
  }
  EXPECT_LT(largest_force<3>(shear_damping_forces<3>(v, kAlpha)), kTol);
  // T (2-42) ... (2-45) as printed; (2-44) lost an entry, restored as ξ_I ζ_I of Table 2.1.
  const std::array<std::array<double, 8>, 4> gamma{{{1, -1, 1, -1, 1, -1, 1, -1},
                                                    {1, 1, -1, -1, -1, -1, 1, 1},
                                                    {1, -1, -1, 1, -1, 1, 1, -1},
                                                    {-1, 1, -1, 1, 1, -1, 1, -1}}};
  for (const auto& mode : gamma) {
    const auto grid = in_grid_order(mode);
    for (int i = 0; i < 3; ++i) {
      CellVectors<3> hourglass;
      for (int node = 0; node < 8; ++node) hourglass[node] = grid[node] * Vec<3>::Unit(i);
      EXPECT_LT(largest_force<3>(shear_damping_forces<3>(hourglass, kAlpha)), kTol);
    }
  }
}

TEST(ShearModeDamping, PureShearModeIsDampedAtEightAlphaOverNodeMass) {
  // Air in a 1 cm cell, Q_s = 0.1: α_s = (Σ m_p / Δx) Q_s c / 4, T (2-48).
  const double cell_mass = 1.225 * std::pow(kCellSize, 3), c = 340, q_s = 0.1;
  const double alpha = shear_damping_coefficient<3>(cell_mass, c, kCellSize, q_s);
  EXPECT_NEAR(alpha, cell_mass / kCellSize * q_s * c / 4, 1e-15 * alpha);
  // v_x = a η_I, v_y = a ξ_I: S_xy = S_yx = 8 a, so f^I = -8 α_s v^I by T (2-47).
  const double a = 0.01, node_mass = cell_mass / 8, dt = 1e-7;
  CellVectors<3> v;
  for (int node = 0; node < 8; ++node) {
    v[node] = a * Vec<3>(natural_coordinate(node, 1), natural_coordinate(node, 0), 0);
  }
  const auto f = shear_damping_forces<3>(v, alpha);
  for (int node = 0; node < 8; ++node) {
    EXPECT_NEAR((f[node] + 8 * alpha * v[node]).norm(), 0, 1e-15 * alpha);
  }
  const double rate = 8 * alpha / node_mass;  // = 16 Q_s c / Δx = 54400 /s
  EXPECT_NEAR(rate, 16 * q_s * c / kCellSize, 1e-9 * rate);
  const int steps = 100;
  for (int step = 0; step < steps; ++step) {
    const auto force = shear_damping_forces<3>(v, alpha);
    for (int node = 0; node < 8; ++node) v[node] += dt / node_mass * force[node];
  }
  const double amplitude = v[0](0) / natural_coordinate(0, 1);
  EXPECT_NEAR(amplitude, a * std::pow(1 - rate * dt, steps), 1e-12 * a);
  // Against the continuous decay a e^{-rate t}: explicit Euler's error, rate² dt t / 2 = 0.16 %.
  EXPECT_NEAR(amplitude, a * std::exp(-rate * dt * steps), 2e-3 * amplitude);
}

TEST(ShearModeDamping, ForcesSumToZeroHaveNoMomentAndDoNegativeWork) {
  std::mt19937 generator(20141124);
  const Vec<3> centre(0.2, 0.4, -0.1);
  for (int sample = 0; sample < 200; ++sample) {
    const CellVectors<3> v = random_velocities(generator);
    const auto f = shear_damping_forces<3>(v, kAlpha);
    Vec<3> total = Vec<3>::Zero(), moment = Vec<3>::Zero();
    for (int node = 0; node < 8; ++node) {
      total += f[node];
      moment += node_position<3>(node, centre).cross(f[node]);
    }
    EXPECT_LT(total.norm(), kTol);
    EXPECT_LT(moment.norm(), kTol);
    EXPECT_LE(power<3>(f, v), 0);
  }
}

TEST(ShearModeDamping, ExplicitStepsWithinTheStiffnessBoundNeverGainEnergy) {
  std::mt19937 generator(7);
  const double node_mass = 0.5;
  // dt at the bound of shear_damping_stiffness: dt 2^3 α = 2 m for one cell.
  const double dt = 2 * node_mass / shear_damping_stiffness<3>(kAlpha);
  for (int sample = 0; sample < 20; ++sample) {
    CellVectors<3> v = random_velocities(generator);
    auto energy = [&] {
      double e = 0;
      for (const auto& node : v) e += 0.5 * node_mass * node.squaredNorm();
      return e;
    };
    double previous = energy();
    for (int step = 0; step < 50; ++step) {
      const auto f = shear_damping_forces<3>(v, kAlpha);
      for (int node = 0; node < 8; ++node) v[node] += dt / node_mass * f[node];
      const double now = energy();
      EXPECT_LE(now, previous * (1 + 1e-14));
      previous = now;
    }
  }
  // Beyond the bound the pure shear mode grows: the bound is sharp.
  CellVectors<3> shear;
  for (int node = 0; node < 8; ++node) {
    shear[node] = Vec<3>(0, natural_coordinate(node, 2), natural_coordinate(node, 1));
  }
  const auto f = shear_damping_forces<3>(shear, kAlpha);
  const double factor = 1 + 1.1 * dt / node_mass * f[0].dot(shear[0]) / shear[0].squaredNorm();
  EXPECT_LT(factor, -1);
}

TEST(ShearModeDamping, ThesisUnsymmetrisedFormWouldBrakeARigidRotation) {
  // T (2-47) applied to each S_ik alone: f_i^I = -α Σ_{k≠i} S_ik Λ_kI.
  auto thesis_forces = [](const CellVectors<3>& v) {
    const Tensor<3> s = mode_amplitudes<3>(v);
    CellVectors<3> f;
    for (int node = 0; node < 8; ++node) {
      f[node].setZero();
      for (int i = 0; i < 3; ++i) {
        for (int k = 0; k < 3; ++k) {
          if (k != i) f[node](i) -= kAlpha * s(i, k) * natural_coordinate(node, k);
        }
      }
    }
    return f;
  };
  CellVectors<3> spin, shear;
  for (int node = 0; node < 8; ++node) {
    const Vec<3> x = node_position<3>(node, Vec<3>::Zero());
    spin[node] = Vec<3>(-x(1), x(0), 0) / kCellSize;
    shear[node] = Vec<3>(x(1), x(0), 0) / kCellSize;
  }
  EXPECT_LT(power<3>(thesis_forces(spin), spin), -0.1 * kAlpha);
  EXPECT_LT(largest_force<3>(shear_damping_forces<3>(spin, kAlpha)), kTol);
  // On a pure shear the two forms agree.
  const auto ours = shear_damping_forces<3>(shear, kAlpha), thesis = thesis_forces(shear);
  for (int node = 0; node < 8; ++node) EXPECT_NEAR((ours[node] - thesis[node]).norm(), 0, kTol);
}

TEST(ShearModeDamping, TwoDimensionalCellDampsAsTheExtrudedEightNodeCell) {
  const double mass = 2e-3, c = 400, q_s = 0.2;
  const double alpha3 = shear_damping_coefficient<3>(mass, c, kCellSize, q_s);
  const double alpha2 = shear_damping_coefficient<2>(mass, c, kCellSize, q_s);
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> uniform(-1, 1);
  CellVectors<2> v2;
  CellVectors<3> v3;
  for (int node = 0; node < 4; ++node) {
    v2[node] = Vec<2>(uniform(generator), uniform(generator));
    v3[node] = v3[node + 4] = Vec<3>(v2[node](0), v2[node](1), 0);
  }
  const auto f2 = shear_damping_forces<2>(v2, alpha2);
  const auto f3 = shear_damping_forces<3>(v3, alpha3);
  for (int node = 0; node < 4; ++node) {
    const Vec<3> pair = f3[node] + f3[node + 4];
    EXPECT_NEAR((f2[node] - pair.head<2>()).norm(), 0, kTol * alpha3);
  }
}

TEST(ShearModeDamping, OneDimensionalCellHasNoShearMode) {
  const CellVectors<1> v{Vec<1>(3), Vec<1>(-5)};
  EXPECT_EQ(largest_force<1>(shear_damping_forces<1>(v, kAlpha)), 0);
}

}  // namespace
}  // namespace mpfd::mpm::damping
