// fdm_solver serve driven through protocol v1 gives exactly what the solver
// gives when called directly: same dts, same state, bit for bit.

#include <gtest/gtest.h>

#include "common/config/scene_loader.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "serve_harness.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;

/// rho, momentum and E of a 2D box export over the whole grid, against the
/// solver's state: the export is in box C order, (i, j) with j fastest.
void expect_state_equals(const cosim::Message& reply, const std::string& region,
                         const EulerSolver& direct) {
  const auto& g = direct.state().grid;
  const auto& u = direct.state().u;
  const auto rho = array_of(reply, region, "rho");
  const auto momentum = array_of(reply, region, "momentum");
  const auto energy = array_of(reply, region, "E");
  ASSERT_EQ(rho.size(), g.cell_count());
  ASSERT_EQ(momentum.size(), 3 * g.cell_count());
  std::size_t n = 0;
  for (int i = 0; i < g.cells()[0]; ++i) {
    for (int j = 0; j < g.cells()[1]; ++j, ++n) {
      const std::size_t c = g.cell_index(i, j, 0);
      EXPECT_EQ(rho[n], u[kDensity][c]) << i << ", " << j;
      EXPECT_EQ(energy[n], u[kEnergy][c]) << i << ", " << j;
      for (std::size_t d = 0; d < 3; ++d)
        EXPECT_EQ(momentum[3 * n + d], u[kMomentumX + d][c]) << i << ", " << j << " axis " << d;
    }
  }
}

TEST(FdmServe, SodTwentyStepsOverInprocEqualTheSolverAdvancedDirectlyBitForBit) {
  ServedFdm fdm;
  const auto ack = fdm.request(setup(sod_text(100), {cell_box("tube", {0}, {100})}));
  const auto scene = config::parse_scene(sod_text(100), "sod.yaml");
  EulerSolver direct(scene, SolverOptions::from_scene(scene));
  double dt = ack.header.setup_ack().stable_dt();
  EXPECT_EQ(dt, direct.stable_dt());
  ASSERT_EQ(ack.header.setup_ack().regions(0).quantities_size(), 3);  // rho, momentum, E

  double time = 0.0;
  cosim::Message reply;
  for (std::uint64_t step = 1; step <= 20; ++step) {
    fdm.hub().set_clock(step, time);
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    add_export(exchange, "tube");
    exchange.header.mutable_exchange()->add_operations()->mutable_propose_dt();
    reply = fdm.request(std::move(exchange));
    direct.advance(dt);
    time += dt;
    const auto& results = reply.header.exchange_result().results();
    ASSERT_EQ(results.size(), 3);
    EXPECT_EQ(results[0].advanced().time(), direct.time());
    EXPECT_EQ(results[1].exported().count(), 100U);
    EXPECT_EQ(results[2].proposed().limited_by(), "cfl");
    dt = results[2].proposed().stable_dt();
    EXPECT_EQ(dt, direct.stable_dt()) << "step " << step;
  }
  expect_state_equals(reply, "tube", direct);
  fdm.shut_down();
  EXPECT_EQ(fdm.last_shutdown().steps_done(), 20U);
  EXPECT_EQ(fdm.stop_reason(), "");
}

TEST(FdmServe, ApplySetOfAHotCellThenAdvanceEqualsWritingTheCellDirectly) {
  ServedFdm fdm;
  fdm.request(setup(still_air_2d_text(),
                    {cell_box("all", {0, 0}, {8, 8}), cell_box("hot", {3, 4}, {4, 5})}));
  const auto scene = config::parse_scene(still_air_2d_text(), "air.yaml");
  EulerSolver direct(scene, SolverOptions::from_scene(scene));
  // A cell at (3, 4), not (4, 3): a transposed write would show in the comparison.
  const double hot[5] = {2.0, 30.0, -10.0, 0.0, 1.0e6 / 0.4 + 0.5 * (900.0 + 100.0) / 2.0};
  EulerState& state = direct.state_for_update({{3, 4, 0}, {4, 5, 1}});
  for (std::size_t v = 0; v < kVariables; ++v) state.u[v][state.grid.cell_index(3, 4, 0)] = hot[v];
  const double dt = direct.stable_dt();

  cosim::Message exchange;
  add_apply(exchange, "hot", v1::ApplyRegion::MODE_SET);
  cosim::add_array(exchange, {"hot", "rho", {}, "kg/m^3"}, std::vector<double>{hot[0]});
  cosim::add_array(exchange, {"hot", "momentum", {1, 3}, "kg/(m^2*s)"},
                   std::vector<double>{hot[1], hot[2], hot[3]});
  cosim::add_array(exchange, {"hot", "E", {}, "J/m^3"}, std::vector<double>{hot[4]});
  double time = 0.0;
  for (int step = 0; step < 3; ++step, time += dt) {
    add_advance(exchange, dt, time);
    fdm.request(std::move(exchange));
    exchange = {};
    direct.advance(dt);
  }
  add_export(exchange, "all");
  expect_state_equals(fdm.request(std::move(exchange)), "all", direct);
}

TEST(FdmServe, ApplyAddIncrementsTheRegionsDensityExactly) {
  ServedFdm fdm;
  fdm.request(setup(still_air_2d_text(), {cell_box("strip", {2, 0}, {3, 8}, {"rho"})}));
  cosim::Message exchange;
  add_apply(exchange, "strip", v1::ApplyRegion::MODE_ADD);
  std::vector<double> deposit(8);
  for (std::size_t n = 0; n < 8; ++n) deposit[n] = 0.125 * static_cast<double>(n);
  cosim::add_array(exchange, {"strip", "rho", {}, "kg/m^3"}, std::vector<double>(deposit));
  add_export(exchange, "strip");
  const auto rho = array_of(fdm.request(std::move(exchange)), "strip", "rho");
  ASSERT_EQ(rho.size(), 8U);
  for (std::size_t n = 0; n < 8; ++n) EXPECT_EQ(rho[n], 1.2 + deposit[n]) << n;
}

TEST(FdmServe, ExportedPressureAndVelocityFollowTheIdealGasOfTheCell) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(10), {cell_box("ends", {4}, {6}, {"rho", "pressure", "velocity"})}));
  cosim::Message exchange;
  exchange.header.mutable_exchange()->add_operations()->mutable_export_region()->set_region("ends");
  const auto reply = fdm.request(std::move(exchange));
  // Cells 4 and 5 hold the left (1, 0, 1) and right (0.125, 0, 0.1) states of Sod.
  EXPECT_EQ(array_of(reply, "ends", "rho"), (std::vector<double>{1.0, 0.125}));
  const auto p = array_of(reply, "ends", "pressure");
  ASSERT_EQ(p.size(), 2U);
  EXPECT_NEAR(p[0], 1.0, 1e-15);  // round-off of p -> e -> p through (gamma - 1) rho e
  EXPECT_NEAR(p[1], 0.1, 1e-15);
  EXPECT_EQ(array_of(reply, "ends", "velocity"), std::vector<double>(6, 0.0));
}

}  // namespace
}  // namespace mpfd::fdm
