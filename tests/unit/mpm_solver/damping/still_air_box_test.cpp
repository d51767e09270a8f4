// Still air with round-off noise in a box of cells, damped by the per-cell
// kernel assembled over the grid as the step will (forces added per node):
// the kernel-level counterpart of T Fig. 2.4. Only the damping acts here.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "mpm_solver/damping/shear_mode_damping.hpp"

namespace mpfd::mpm::damping {
namespace {

constexpr int kCells = 4;              // per axis
constexpr int kNodes = kCells + 1;     // per axis
constexpr double kBoxCellSize = 0.01;  // m
constexpr double kDensity = 1.225;     // kg/m^3, air (T (2-59) table)
constexpr double kSoundSpeed = 340;    // m/s
constexpr double kQs = 0.1;

int node_index(int i, int j, int k) {
  return i + kNodes * (j + kNodes * k);
}
int corner_node(int i, int j, int k, int corner) {
  return node_index(i + (corner & 1), j + ((corner >> 1) & 1), k + ((corner >> 2) & 1));
}

struct Box {
  std::vector<double> mass = std::vector<double>(kNodes * kNodes * kNodes, 0.0);
  std::vector<Vec<3>> velocity = std::vector<Vec<3>>(mass.size(), Vec<3>::Zero());
  double alpha = 0;

  template <class CellBody>
  static void for_each_cell(const CellBody& body) {
    for (int k = 0; k < kCells; ++k) {
      for (int j = 0; j < kCells; ++j) {
        for (int i = 0; i < kCells; ++i) body(i, j, k);
      }
    }
  }
  CellVectors<3> cell_velocities(int i, int j, int k) const {
    CellVectors<3> v;
    for (int c = 0; c < 8; ++c) v[c] = velocity[corner_node(i, j, k, c)];
    return v;
  }
  // Σ over cells of Σ_{i≠k} D_ik², D the symmetrised S of T (2-46).
  double shear_measure() const {
    double sum = 0;
    for_each_cell([&](int i, int j, int k) {
      const Tensor<3> s = mode_amplitudes<3>(cell_velocities(i, j, k));
      Tensor<3> d = 0.5 * (s + s.transpose());
      d.diagonal().setZero();
      sum += d.squaredNorm();
    });
    return sum;
  }
  Vec<3> momentum() const {
    Vec<3> p = Vec<3>::Zero();
    for (std::size_t n = 0; n < mass.size(); ++n) p += mass[n] * velocity[n];
    return p;
  }
  double kinetic_energy() const {
    double e = 0;
    for (std::size_t n = 0; n < mass.size(); ++n) e += 0.5 * mass[n] * velocity[n].squaredNorm();
    return e;
  }
  void step(double dt) {
    std::vector<Vec<3>> force(mass.size(), Vec<3>::Zero());
    for_each_cell([&](int i, int j, int k) {
      const auto f = shear_damping_forces<3>(cell_velocities(i, j, k), alpha);
      for (int c = 0; c < 8; ++c) force[corner_node(i, j, k, c)] += f[c];
    });
    for (std::size_t n = 0; n < mass.size(); ++n) velocity[n] += dt / mass[n] * force[n];
  }
};

TEST(StillAirBox, ShearNoiseDiesWhileMomentumAndEnergyBoundsHold) {
  Box box;
  const double cell_mass = kDensity * std::pow(kBoxCellSize, 3);
  box.alpha = shear_damping_coefficient<3>(cell_mass, kSoundSpeed, kBoxCellSize, kQs);
  Box::for_each_cell([&](int i, int j, int k) {
    for (int c = 0; c < 8; ++c) box.mass[corner_node(i, j, k, c)] += cell_mass / 8;
  });
  std::mt19937 generator(2014);
  std::normal_distribution<double> noise(0, 1e-3);  // m/s
  for (auto& v : box.velocity) v = Vec<3>(noise(generator), noise(generator), noise(generator));

  // Every node here has Σ_cells 2^3 α_s / m_I = 64 α_s / m_cell; a CFL 0.5 step is
  // 0.5 Δx / c, well inside the energy bound dt <= 2 m_I / Σ 2^3 α_s = Δx / (8 Q_s c).
  const double dt = 0.5 * kBoxCellSize / kSoundSpeed;
  ASSERT_LE(dt * 64 * box.alpha / cell_mass, 2.0);
  const Vec<3> momentum0 = box.momentum();
  const double shear0 = box.shear_measure();
  double energy = box.kinetic_energy();
  for (int step = 0; step < 400; ++step) {
    box.step(dt);
    const double now = box.kinetic_energy();
    ASSERT_LE(now, energy * (1 + 1e-14)) << "step " << step;
    energy = now;
  }
  EXPECT_LT((box.momentum() - momentum0).norm(), 1e-15 * cell_mass);
  // Measured after 400 steps (5.9 ms): shear 1.2e-4 of the start (long waves go
  // last), kinetic energy 46 % (the compression and hourglass noise is not shear).
  EXPECT_LT(box.shear_measure(), 5e-4 * shear0);
}

}  // namespace
}  // namespace mpfd::mpm::damping
