// The real `fdm_solver serve` executable as a child process, driven over ipc
// by a coupler (Hub) in this test: a Sod run step by step, and a coupler
// that dies, which the solver must notice within its idle timeout.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>

#include "child_process.hpp"
#include "common/config/scene_loader.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "tests/unit/fdm_solver/serve/serve_harness.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// Allowed lateness: process start-up and scheduling on a loaded 2-core machine.
constexpr milliseconds margin{2000};

cosim::TransportOptions coupler_options() {
  cosim::TransportOptions options;
  options.reply_timeout = milliseconds{10000};  // covers the child's start-up
  return options;
}

std::unique_ptr<mpfd::testing::ChildProcess> start_solver(const std::string& endpoint,
                                                          const std::string& idle_seconds,
                                                          const std::string& tag) {
  return mpfd::testing::start_serve(MPFD_FDM_SOLVER, endpoint, idle_seconds, tag);
}

TEST(FdmServeProcess, TwentySodStepsOverIpcMatchTheSolverBitForBitAndShutdownExitsZero) {
  zmq::context_t context;
  cosim::Hub hub(context, cosim::testing::unique_bind_endpoint(cosim::Transport::ipc),
                 coupler_options());
  auto solver = start_solver(hub.endpoint(), "10", "sod");
  const std::vector<std::string> peers{"fdm"};
  EXPECT_EQ(hub.accept(peers, "run-process").front().software(), "mpfd fdm_solver");

  hub.send("fdm", setup(sod_text(100), {cell_box("tube", {0}, {100})}));
  double dt = hub.receive_from("fdm").header.setup_ack().stable_dt();
  const auto scene = config::parse_scene(sod_text(100), "sod.yaml");
  EulerSolver direct(scene, {});
  double time = 0.0;
  for (std::uint64_t step = 1; step <= 20; ++step) {
    hub.set_clock(step, time);
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    exchange.header.mutable_exchange()->add_operations()->mutable_propose_dt();
    hub.send("fdm", std::move(exchange));
    direct.advance(dt);
    const auto reply = hub.receive_from("fdm");
    time += dt;
    dt = reply.header.exchange_result().results(1).proposed().stable_dt();
  }
  cosim::Message exchange;
  add_export(exchange, "tube");
  hub.send("fdm", std::move(exchange));
  const auto exported = hub.receive_from("fdm");
  EXPECT_EQ(array_of(exported, "tube", "rho"), direct.state().u[kDensity]);
  EXPECT_EQ(array_of(exported, "tube", "E"), direct.state().u[kEnergy]);

  cosim::Message shutdown;
  shutdown.header.mutable_shutdown()->set_reason("test done");
  hub.send("fdm", std::move(shutdown));
  EXPECT_EQ(hub.receive_from("fdm").header.shutdown_ack().steps_done(), 20U);
  EXPECT_EQ(solver->wait_for(milliseconds{5000}), 0) << solver->error_output();
}

TEST(FdmServeProcess, SolverExitsNonZeroWithinItsIdleTimeoutWhenTheCouplerDies) {
  zmq::context_t context;
  auto hub = std::make_unique<cosim::Hub>(
      context, cosim::testing::unique_bind_endpoint(cosim::Transport::ipc), coupler_options());
  const std::string endpoint = hub->endpoint();
  auto solver = start_solver(endpoint, "1", "dead-coupler");
  const std::vector<std::string> peers{"fdm"};
  hub->accept(peers, "run-dies");
  hub->send("fdm", setup(sod_text(100), {}));
  hub->receive_from("fdm");
  const auto died = Clock::now();
  hub.reset();  // the coupler dies without Shutdown

  const auto code = solver->wait_for(milliseconds{1000} + margin);
  ASSERT_TRUE(code.has_value()) << "the solver outlived its 1 s idle timeout by over 2 s";
  EXPECT_NE(*code, 0);
  EXPECT_GE(Clock::now() - died, milliseconds{900});
  EXPECT_THAT(solver->error_output(),
              ::testing::AllOf(::testing::HasSubstr("solver 'fdm': coupler at " + endpoint),
                               ::testing::HasSubstr("within 1.0 s")));
}

}  // namespace
}  // namespace mpfd::fdm
