// The per-step pipeline: advection, classification, energy split and closure.

#include "fdm_solver/tracer/multi_material_tracker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "common/core/error.hpp"
#include "tests/unit/common/eos/eos_test_materials.hpp"

namespace mpfd::fdm {
namespace {

namespace tm = eos::test_materials;

constexpr TracerBoundaries kAllOutflow{TracerFace::outflow, TracerFace::outflow,
                                       TracerFace::outflow, TracerFace::outflow,
                                       TracerFace::outflow, TracerFace::outflow};

/// 1D, 10 cells of 1 cm: products (material 0) in cells 0-4, air in 5-9.
struct Slab {
  static constexpr double e_products = 4.0e6;
  grid::UniformGrid g{{0, 0, 0}, {0.01, 0.01, 0.01}, {10, 1, 1}};
  std::vector<double> material, rho, e, p, u;
  MultiMaterialTracker tracker;
  Slab()
      : material(cells(0.0, 1.0)),
        rho(cells(50.0, tm::kAirDensity)),
        e(cells(e_products, tm::kAirEnergy)),
        p(10, 0.0),
        u(10, 2.5),  // 0.25 cell per 1 ms
        tracker(g, {tm::kTnt, tm::kAir}, material, rho, e, 4) {}
  static std::vector<double> cells(double products, double air) {
    std::vector<double> v(10, air);
    std::fill(v.begin(), v.begin() + 5, products);
    return v;
  }
  void step() {
    tracker.advect({{u, {}, {}}}, 1e-3, kAllOutflow);
    tracker.update_pressure(rho, e, p);
  }
};

TEST(MultiMaterialTracker, SingleMaterialCellsTakeTheirOwnEosPressure) {
  Slab s;
  const ClosureReport r = s.tracker.update_pressure(s.rho, s.e, s.p);
  EXPECT_EQ(r.mixed_cells, 0u);
  EXPECT_DOUBLE_EQ(s.p[2], tm::kTnt.pressure(50.0, s.e_products));
  EXPECT_DOUBLE_EQ(s.p[7], tm::kAir.pressure(tm::kAirDensity, tm::kAirEnergy));
}

TEST(MultiMaterialTracker, MixedCellBalancesPressureAndConservesMassAndEnergy) {
  Slab s;
  s.tracker.update_pressure(s.rho, s.e, s.p);
  s.rho[5] = 20.0;  // what the sweeps would have put into the cell the products enter
  s.e[5] = 1.0e6;
  s.step();
  const MaterialMap& map = s.tracker.materials();
  ASSERT_TRUE(map.is_mixed(5));
  EXPECT_NEAR(map.volume_fraction(5, 0), 0.25, 1e-12);  // one of four tracers, T (3-23)
  const MaterialStates& st = s.tracker.states();
  EXPECT_EQ(st.status[5], ClosureStatus::converged);
  const double theta0 = map.volume_fraction(5, 0);
  const double rho0 = st.density[st.at(0, 5)], rho1 = st.density[st.at(1, 5)];
  const double e0 = st.energy[st.at(0, 5)], e1 = st.energy[st.at(1, 5)];
  const double p0 = tm::kTnt.pressure(rho0, e0), p1 = tm::kAir.pressure(rho1, e1);
  EXPECT_NEAR(p0, p1, 1e-10 * p0);                                          // T (3-24)
  EXPECT_NEAR(theta0 * rho0 + (1 - theta0) * rho1, 20.0, 1e-10 * 20.0);     // T (3-28)
  EXPECT_NEAR(theta0 * rho0 * e0 + (1 - theta0) * rho1 * e1, 20.0 * 1.0e6,  // cell energy
              1e-10 * 2.0e7);
  EXPECT_NEAR(s.p[5], p0, 1e-10 * p0);
}

TEST(MultiMaterialTracker, NewcomerMaterialStartsFromItsNeighboursEnergy) {
  Slab s;
  s.tracker.update_pressure(s.rho, s.e, s.p);
  s.step();  // e_c of cell 5 unchanged: delta_e_c = 0, only the common factor acts
  const MaterialStates& st = s.tracker.states();
  ASSERT_TRUE(s.tracker.materials().is_mixed(5));
  // Products are new to cell 5: they start at cell 4's e, air at cell 5's own.
  EXPECT_NEAR(st.energy[st.at(0, 5)] / st.energy[st.at(1, 5)], s.e_products / tm::kAirEnergy,
              1e-12 * s.e_products / tm::kAirEnergy);
}

TEST(MultiMaterialTracker, InterfaceCellTurnsSingleOnceTheProductsFillIt) {
  Slab s;
  s.tracker.update_pressure(s.rho, s.e, s.p);
  for (int n = 0; n < 4; ++n) s.step();  // one full cell
  const MaterialMap& map = s.tracker.materials();
  EXPECT_EQ(map.material[5], 0);
  EXPECT_EQ(map.material[6], 1);
  EXPECT_EQ(map.material[0], 0);  // emptied by the inflow-free left face: keeps products
  EXPECT_EQ(s.tracker.tracers().size(), 10u * 4u - 4u);
}

/// Everything restore() takes, copied out of a tracker between steps.
TrackerState saved(const MultiMaterialTracker& tracker) {
  return {tracker.tracers(), tracker.materials(), tracker.states()};
}

void expect_same_tracker(const MultiMaterialTracker& a, const MultiMaterialTracker& b) {
  EXPECT_EQ(a.tracers().position, b.tracers().position);
  EXPECT_EQ(a.tracers().material, b.tracers().material);
  EXPECT_EQ(a.tracers().volume, b.tracers().volume);
  EXPECT_EQ(a.materials().material, b.materials().material);
  EXPECT_EQ(a.materials().theta, b.materials().theta);
  EXPECT_EQ(a.states().energy, b.states().energy);
  EXPECT_EQ(a.states().density, b.states().density);
  EXPECT_EQ(a.states().cell_energy, b.states().cell_energy);
  EXPECT_EQ(a.states().status, b.states().status);
}

TEST(MultiMaterialTracker, SeedsItsTracersAtTheirFirstUseAsTheConstructorWould) {
  Slab s;
  s.tracker.update_pressure(s.rho, s.e, s.p);  // the initial pressure needs no tracer
  EXPECT_TRUE(s.tracker.tracers_pending());
  const TracerSet expected = seed_from_materials(s.g, s.material, 4);
  const TracerSet& seeded = s.tracker.tracers();
  EXPECT_FALSE(s.tracker.tracers_pending());
  EXPECT_EQ(seeded.position, expected.position);
  EXPECT_EQ(seeded.material, expected.material);
  EXPECT_EQ(seeded.volume, expected.volume);
  EXPECT_EQ(s.tracker.bins().count(2, 0), 4u);

  Slab stepped;  // advect() seeds first, then moves them by u dt = 2.5 mm
  stepped.step();
  EXPECT_FALSE(stepped.tracker.tracers_pending());
  EXPECT_DOUBLE_EQ(stepped.tracker.tracers().position[0][0], expected.position[0][0] + 2.5e-3);
}

TEST(MultiMaterialTracker, ARestoreBeforeTheFirstUseNeverSeeds) {
  Slab a;
  a.step();
  Slab b;
  ASSERT_TRUE(b.tracker.tracers_pending());
  b.tracker.restore(saved(a.tracker));
  EXPECT_FALSE(b.tracker.tracers_pending());
  EXPECT_EQ(b.tracker.tracers().position, a.tracker.tracers().position);
}

TEST(MultiMaterialTracker, RefusesFewerThanOneTracerPerAxisWhenConstructed) {
  const Slab s;
  EXPECT_THROW(MultiMaterialTracker(s.g, {tm::kTnt, tm::kAir}, s.material, s.rho, s.e, 0), Error);
}

TEST(MultiMaterialTracker, RestoredStateContinuesBitForBitAsTheTrackerThatHadIt) {
  Slab a;
  a.tracker.update_pressure(a.rho, a.e, a.p);
  a.rho[5] = 20.0;  // products entering cell 5 make it mixed, with a closure to carry over
  a.e[5] = 1.0e6;
  for (int s = 0; s < 3; ++s) a.step();
  ASSERT_GT(closure_report(a.tracker.states()).mixed_cells, 0u);

  Slab b;  // freshly seeded: its tracers and energies differ from a's
  b.rho = a.rho;
  b.e = a.e;
  b.tracker.restore(saved(a.tracker));
  expect_same_tracker(a.tracker, b.tracker);
  for (int s = 0; s < 3; ++s) {
    a.step();
    b.step();
  }
  expect_same_tracker(a.tracker, b.tracker);
  EXPECT_EQ(a.p, b.p);
}

TEST(MultiMaterialTracker, RestoreRefusesAStateThatDoesNotFitAndKeepsItsOwn) {
  Slab a;
  a.step();
  const TrackerState good = saved(a.tracker);
  Slab b;
  const TrackerState before = saved(b.tracker);
  const auto refused = [&](TrackerState state, const std::string& text) {
    try {
      b.tracker.restore(std::move(state));
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(text), std::string::npos) << error.what();
      return;
    }
    ADD_FAILURE() << "restore accepted a state with " << text;
  };
  TrackerState outside = good;
  outside.tracers.position[0][3] = 0.2;  // the slab ends at 0.1 m
  refused(outside, "tracer 3 is at 0.200000 m along axis 0, outside the grid");
  TrackerState third_material = good;
  third_material.tracers.material[0] = 2;
  refused(third_material, "tracer 0 has material 2, outside [0, 2)");
  TrackerState short_theta = good;
  short_theta.materials.theta.pop_back();
  refused(short_theta, "theta has 19 values; expected 20");
  TrackerState bad_status = good;
  bad_status.states.status[4] = static_cast<ClosureStatus>(7);
  refused(bad_status, "cell 4 has closure status 7");
  const TrackerState after = saved(b.tracker);
  EXPECT_EQ(after.tracers.position, before.tracers.position);
  EXPECT_EQ(after.materials.theta, before.materials.theta);
  EXPECT_EQ(after.states.energy, before.states.energy);
}

}  // namespace
}  // namespace mpfd::fdm
