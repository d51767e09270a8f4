// MpmSolver::map_next_step, the early map a coupler's ghost_nodes export
// makes: its box holds the full scatter's node mass, momentum and e_I (T
// (2-12), (2-9)) bit for bit; the advance that starts from it is the plain
// advance bit for bit; particles injected onto it change the step only in
// the last bits; and a removal, a load on a node no particle reaches, or an
// injection beyond the mapped blocks makes the advance map afresh (bit for
// bit the plain advance again).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/mpm_test_scenes.hpp"

namespace mpfd::mpm {
namespace {

using testing::gas_body;
using testing::gas_scene;

struct Case {
  std::string shape;
  std::string update;
  std::string options;  ///< more solver.mpm keys
  std::string x_upper = "wall";
};

/// A blast in 32 x 16 cells, the air filling x < 0.75 only (it spreads to
/// x = 0.84 m in the steps run here; the blocks beyond hold no particle).
config::Scene blast(const Case& c) {
  return gas_scene(
      "[1, 0.5, 0.015625]", "[32, 16, 1]",
      "bodies:\n" + gas_body("hot", "[0, 0, 0]", "[0.3, 0.5, 0.015625]", 4.0, 10.0) +
          gas_body("air", "[0.3, 0, 0]", "[0.75, 0.5, 0.015625]", 1.0, 1.0, "[0.3, 0.2, 0]") +
          "boundaries: {x_lower: wall, x_upper: " + c.x_upper +
          ", y_lower: wall, y_upper: wall}\n"
          "solver: {method: mpm, mpm: {shape_function: " +
          c.shape + ", update: " + c.update + c.options + "}}\n");
}

constexpr grid::Index3 kBoxLo{9, 0, 0}, kBoxHi{13, 17, 1};  // a ghost-node box of w = 4

/// Every particle's position, velocity, density and energy, in index order.
std::vector<double> state(const MpmSolver& solver) {
  const ParticleSet& ps = solver.particles();
  std::vector<double> out;
  for (std::size_t p = 0; p < ps.size(); ++p) {
    for (int a = 0; a < 3; ++a) {
      out.push_back(ps.position[static_cast<std::size_t>(a)][p]);
      out.push_back(ps.velocity[static_cast<std::size_t>(a)][p]);
    }
    out.push_back(ps.density[p]);
    out.push_back(ps.specific_internal_energy[p]);
  }
  return out;
}

/// Eight hot particles from x = 0.2, inside the mapped blocks, or from x = 0.97, beyond them.
ParticleBatch hot_particles(double x) {
  ParticleBatch batch;
  batch.resize(8);
  batch.stress.clear();
  for (std::size_t i = 0; i < 8; ++i) {
    batch.id[i] = 900000 + i;
    batch.position[3 * i] = x + 0.003 * static_cast<double>(i);
    batch.position[3 * i + 1] = 0.03 + 0.055 * static_cast<double>(i);
    batch.position[3 * i + 2] = 0.007;
    batch.velocity[3 * i] = 0.5;
    batch.volume[i] = 0.25 * 0.03125 * 0.03125 * 0.015625;
    batch.mass[i] = 3.0 * batch.volume[i];
    batch.internal_energy[i] = batch.mass[i] * 2.0;
    batch.material[i] = 0;
  }
  return batch;
}

class NextStepMapTest : public ::testing::TestWithParam<Case> {
 protected:
  /// Two solvers of the same blast after 12 plain steps (off their lattice).
  void SetUp() override {
    const auto scene = blast(GetParam());
    early_ = std::make_unique<MpmSolver>(scene, MpmSettings::from_scene(scene));
    plain_ = std::make_unique<MpmSolver>(scene, MpmSettings::from_scene(scene));
    for (int step = 0; step < 12; ++step) {
      const double dt = plain_->stable_dt();
      early_->advance(dt);
      plain_->advance(dt);
    }
  }
  /// One step of both: `early_` maps it first, `between` acts on both in between.
  template <class Between>
  void step_both(const Between& between) {
    early_->map_next_step(kBoxLo, kBoxHi);
    between(*early_);
    between(*plain_);
    const double dt = plain_->stable_dt();
    early_->advance(dt);
    plain_->advance(dt);
  }
  std::unique_ptr<MpmSolver> early_, plain_;
};

TEST_P(NextStepMapTest, ItsBoxIsTheFullScatterBitForBit) {
  NodeBoxMap from_map, from_box;
  early_->map_next_step(kBoxLo, kBoxHi);
  ASSERT_TRUE(early_->next_step_mapped(kBoxLo, kBoxHi));
  EXPECT_FALSE(early_->next_step_mapped({8, 0, 0}, kBoxHi));
  early_->read_next_step_box(kBoxLo, kBoxHi, from_map);
  early_->map_particles_to_node_box(kBoxLo, kBoxHi, from_box);
  EXPECT_EQ(from_map.mass, from_box.mass);
  EXPECT_EQ(from_map.momentum, from_box.momentum);
  EXPECT_EQ(from_map.internal_energy, from_box.internal_energy);
  double energy = 0.0;
  for (const double e : from_map.internal_energy) energy += e;
  EXPECT_GT(energy, 0.0);
}

TEST_P(NextStepMapTest, TheAdvanceFromItIsThePlainAdvanceBitForBit) {
  for (int step = 0; step < 3; ++step) {
    step_both([](MpmSolver&) {});
    EXPECT_TRUE(early_->last_advance_was_premapped());
    EXPECT_FALSE(early_->has_next_step_map());  // the advance used it up
  }
  EXPECT_EQ(state(*early_), state(*plain_));
}

TEST_P(NextStepMapTest, InjectedParticlesJoinItAndChangeOnlyTheLastBits) {
  step_both([](MpmSolver& s) { s.inject_particles(hot_particles(0.2)); });
  EXPECT_TRUE(early_->last_advance_was_premapped());
  const auto a = state(*early_), b = state(*plain_);
  ASSERT_EQ(a.size(), b.size());
  double largest = 0.0, scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    largest = std::max(largest, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(b[i]));
  }
  EXPECT_LE(largest, 1e-12 * scale);
  const MpmTotals ta = early_->totals(), tb = plain_->totals();
  EXPECT_EQ(ta.mass, tb.mass);
  EXPECT_NEAR(ta.kinetic_energy + ta.internal_energy, tb.kinetic_energy + tb.internal_energy,
              1e-13 * (tb.kinetic_energy + tb.internal_energy));
}

TEST_P(NextStepMapTest, ChangesItCannotFollowMakeTheAdvanceMapAfresh) {
  // A removal: the map is dropped.
  step_both([](MpmSolver& s) {
    std::vector<std::uint8_t> flags(s.particles().size(), 0);
    flags[3] = flags[40] = 1;
    static_cast<void>(s.remove_particles(flags));
  });
  EXPECT_FALSE(early_->last_advance_was_premapped());
  // A load on a node of a block no particle reaches (x = 0.97 m, node 31; the
  // air has spread to x = 0.84 m, storage block 7, nodes 27...30).
  step_both([](MpmSolver& s) {
    s.queue_node_load({{31, 5, 0}, NodeLoad::Quantity::mass, false, {1e-6, 0, 0}});
  });
  EXPECT_FALSE(early_->last_advance_was_premapped());
  // Particles injected beyond the mapped blocks.
  step_both([](MpmSolver& s) { s.inject_particles(hot_particles(0.97)); });
  EXPECT_FALSE(early_->last_advance_was_premapped());
  EXPECT_EQ(state(*early_), state(*plain_));
}

INSTANTIATE_TEST_SUITE_P(Stencils, NextStepMapTest,
                         ::testing::Values(Case{"linear", "musl", ""}, Case{"gimp", "usavg", ""},
                                           Case{"cpgimp", "usavg", ""}, Case{"linear", "usl", ""},
                                           // per-node sums the map zeroes: damping, face tractions
                                           Case{"gimp", "musl", ", shear_damping: 0.2",
                                                "non_reflecting"}),
                         [](const auto& test) {
                           return test.param.shape + "_" + test.param.update +
                                  (test.param.options.empty() ? "" : "_damped_open");
                         });

}  // namespace
}  // namespace mpfd::mpm
