// The real `mpm_solver serve` executable as a child process, driven over ipc
// by a coupler (Hub) in this test: the blast stepped with the CFDMP
// operations of proto/README.md §6 (inject, apply interface_nodes, advance,
// export ghost_nodes, remove crossed, propose dt) matches an in-process
// MpmSolver bit for bit; a coupler that dies is noticed within the idle timeout.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>

#include "child_process.hpp"
#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::mpm {
namespace {

using namespace testing;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr milliseconds margin{2000};  // process start-up on a loaded 2-core machine

std::unique_ptr<mpfd::testing::ChildProcess> start_solver(const std::string& endpoint,
                                                          const std::string& idle_seconds,
                                                          const std::string& tag) {
  return mpfd::testing::start_serve(MPFD_MPM_SOLVER, endpoint, idle_seconds, tag);
}

TEST(MpmServeProcess, ThirtyCfdmpStepsOverIpcMatchTheSolverBitForBitAndShutdownExitsZero) {
  zmq::context_t context;
  cosim::Hub hub(context, cosim::testing::unique_bind_endpoint(cosim::Transport::ipc),
                 test_options());
  auto solver = start_solver(hub.endpoint(), "10", "blast");
  const std::vector<std::string> peers{"mpm"};
  EXPECT_EQ(hub.accept(peers, "run-process").front().software(), "mpfd mpm_solver");
  auto regions = cfdmp_regions();
  regions.push_back(region("all", v1::REGION_KIND_PARTICLES, {0, 0, 0}, {16, 16, 1},
                           {"id", "position", "velocity"}));
  hub.send("mpm", setup(blast_text(), regions));
  double dt = hub.receive_from("mpm").header.setup_ack().stable_dt();

  const auto scene = config::parse_scene(blast_text(), "blast.yaml");
  MpmSolver direct(scene, MpmSettings::from_scene(scene));
  double time = 0.0;
  std::uint64_t crossed = 0;
  const std::vector<double> force(17 * 3, 0.0);  // the FDM side's term: none in this test
  for (std::uint64_t step = 1; step <= 30; ++step) {
    hub.set_clock(step, time);
    cosim::Message exchange;
    auto& apply = *add_op(exchange).mutable_apply();
    apply.set_region("interface_nodes");
    apply.set_mode(v1::ApplyRegion::MODE_ADD);
    cosim::add_array(exchange, {"interface_nodes", "internal_force", {17, 3}, "N"},
                     std::span<const double>(force));
    add_advance(exchange, dt, time);
    add_export(exchange, "ghost_nodes");
    auto& remove = *add_op(exchange).mutable_remove();
    remove.set_group("crossed");
    remove.set_left_region("mpm_zone");
    add_propose(exchange);
    hub.send("mpm", std::move(exchange));

    direct.advance(dt);
    std::vector<std::uint8_t> outside(direct.particles().size(), 0);
    for (std::size_t p = 0; p < outside.size(); ++p) {
      const double x = direct.particles().position[0][p];
      outside[p] = x < 0.25 || x >= 0.75 ? 1 : 0;  // mpm_zone: cells x [4, 12)
    }
    const auto removed = direct.remove_particles(outside);

    const auto reply = hub.receive_from("mpm");
    const auto& results = reply.header.exchange_result().results();
    ASSERT_EQ(results.size(), 5);
    ASSERT_EQ(results[3].removed().removed(), removed.size());
    EXPECT_EQ(array_of<std::uint64_t>(reply, "crossed", "id"), removed.id);
    crossed += removed.size();
    time += dt;
    dt = results[4].proposed().stable_dt();
    ASSERT_EQ(dt, direct.stable_dt());
  }
  EXPECT_GT(crossed, 0U);
  cosim::Message exchange;
  add_export(exchange, "all");
  hub.send("mpm", std::move(exchange));
  const auto exported = hub.receive_from("mpm");
  const auto position = array_of(exported, "all", "position");
  const ParticleSet& ps = direct.particles();
  ASSERT_EQ(position.size(), 3 * ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p)
    for (std::size_t a = 0; a < 3; ++a) ASSERT_EQ(position[3 * p + a], ps.position[a][p]);

  cosim::Message shutdown;
  shutdown.header.mutable_shutdown()->set_reason("test done");
  hub.send("mpm", std::move(shutdown));
  EXPECT_EQ(hub.receive_from("mpm").header.shutdown_ack().steps_done(), 30U);
  EXPECT_EQ(solver->wait_for(milliseconds{5000}), 0) << solver->error_output();
}

TEST(MpmServeProcess, SolverExitsNonZeroWithinItsIdleTimeoutWhenTheCouplerDies) {
  zmq::context_t context;
  auto hub = std::make_unique<cosim::Hub>(
      context, cosim::testing::unique_bind_endpoint(cosim::Transport::ipc), test_options());
  const std::string endpoint = hub->endpoint();
  auto solver = start_solver(endpoint, "1", "dead-coupler");
  const std::vector<std::string> peers{"mpm"};
  hub->accept(peers, "run-dies");
  hub->send("mpm", setup(blast_text(), {}));
  hub->receive_from("mpm");
  const auto died = Clock::now();
  hub.reset();  // the coupler dies without Shutdown

  const auto code = solver->wait_for(milliseconds{1000} + margin);
  ASSERT_TRUE(code.has_value()) << "the solver outlived its 1 s idle timeout by over 2 s";
  EXPECT_NE(*code, 0);
  EXPECT_GE(Clock::now() - died, milliseconds{900});
  EXPECT_THAT(solver->error_output(), ::testing::HasSubstr("within 1.0 s"));
}

}  // namespace
}  // namespace mpfd::mpm
