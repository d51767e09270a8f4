#include <gtest/gtest.h>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/hub.hpp"
#include "echo_solver.hpp"
#include "test_endpoints.hpp"

namespace mpfd::cosim {
namespace {

using testing::SolverThread;

TransportOptions quick_options() {
  TransportOptions options;
  options.reply_timeout = std::chrono::milliseconds{3000};
  options.idle_timeout = std::chrono::milliseconds{3000};
  return options;
}

Message exchange_for(const std::string& region, std::vector<double> values) {
  Message message;
  auto* exchange = message.header.mutable_exchange();
  exchange->add_operations()->mutable_apply()->set_region(region);
  exchange->add_operations()->mutable_advance()->set_dt(1e-7);
  exchange->add_operations()->mutable_export_region()->set_region(region);
  exchange->add_operations()->mutable_propose_dt();
  add_array(message, {region, "rho", {}, "kg/m^3"}, std::move(values));
  return message;
}

class RoundTrip : public ::testing::TestWithParam<Transport> {};

TEST_P(RoundTrip, CouplerAndTwoSolversExchangeArraysStepByStep) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(GetParam()), quick_options());
  const std::vector<std::string> peers{"fdm", "mpm"};
  std::vector<std::unique_ptr<SolverThread>> solvers;
  for (const auto& name : peers) {
    solvers.push_back(std::make_unique<SolverThread>([&context, &hub, name] {
      Participant participant(context, hub.endpoint(), name, quick_options());
      v1::Hello hello;
      hello.set_software("echo stub");
      participant.connect(hello);
      testing::serve_echo(participant);
    }));
  }
  const auto hellos = hub.accept(peers, "run-roundtrip");
  EXPECT_EQ(hellos[1].software(), "echo stub");

  for (std::uint64_t step = 1; step <= 20; ++step) {
    hub.set_clock(step, static_cast<double>(step) * 1e-7);
    for (const auto& peer : peers) {
      hub.send(peer, exchange_for("strip", std::vector<double>(1000, static_cast<double>(step))));
    }
    const auto replies = hub.gather(peers);
    for (const auto& reply : replies) {
      EXPECT_EQ(reply.header.envelope().step(), step);
      EXPECT_EQ(reply.header.envelope().run_id(), "run-roundtrip");
      EXPECT_EQ(reply.header.exchange_result().results_size(), 4);
      const auto rho = view_array<double>(reply, "strip", "rho");
      ASSERT_EQ(rho.values().size(), 1000U);
      EXPECT_EQ(rho.values()[999], 2.0 * static_cast<double>(step));
    }
    EXPECT_EQ(replies[0].header.exchange_result().results(3).proposed().stable_dt(), 2e-7);
    EXPECT_EQ(replies[1].header.envelope().sender(), "mpm");
  }
  for (const auto& peer : peers) {
    Message shutdown;
    shutdown.header.mutable_shutdown()->set_reason("test done");
    hub.send(peer, std::move(shutdown));
    EXPECT_TRUE(hub.receive_from(peer).header.has_shutdown_ack());
  }
  for (auto& solver : solvers) solver->join_and_rethrow();
}

INSTANTIATE_TEST_SUITE_P(Transports, RoundTrip,
                         ::testing::Values(Transport::inproc, Transport::ipc, Transport::tcp),
                         testing::transport_test_name);

TEST(VersionNegotiation, SolverSpeakingOnlyV2GetsAClearErrorOnBothSides) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::inproc), quick_options());
  std::string solver_error;
  SolverThread solver([&] {
    Participant participant(context, hub.endpoint(), "fdm", quick_options());
    v1::Hello hello;
    hello.set_min_major(2);
    hello.set_max_major(2);
    try {
      participant.connect(hello);
    } catch (const Error& error) {
      solver_error = error.what();
    }
  });
  const std::vector<std::string> peers{"fdm"};
  try {
    hub.accept(peers, "run-v");
    FAIL() << "a v2-only solver was accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what())
                  .find("solver 'fdm' speaks protocol v2..v2, the coupler "
                        "speaks v1"),
              std::string::npos)
        << error.what();
  }
  solver.join_and_rethrow();
  EXPECT_NE(solver_error.find("ERROR_CODE_VERSION_MISMATCH"), std::string::npos) << solver_error;
}

TEST(VersionNegotiation, EnvelopeWithAnotherMajorIsRejectedNamingTheSender) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::inproc), quick_options());
  zmq::socket_t raw(context, zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "mpm");
  raw.set(zmq::sockopt::linger, 0);
  raw.connect(hub.endpoint());
  v1::Header header;
  header.mutable_envelope()->set_protocol_major(3);
  header.mutable_envelope()->set_sender("mpm");
  header.mutable_hello();
  raw.send(zmq::buffer(header.SerializeAsString()));
  try {
    hub.receive_from("mpm");
    FAIL() << "a v3 envelope was accepted";
  } catch (const Error& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("solver 'mpm'"), std::string::npos) << text;
    EXPECT_NE(text.find("speaks v3, this build speaks v1"), std::string::npos) << text;
  }
}

TEST(Transport, GarbageFromAPeerIsAnErrorNotACrash) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::ipc), quick_options());
  zmq::socket_t raw(context, zmq::socket_type::dealer);
  raw.set(zmq::sockopt::routing_id, "fdm");
  raw.set(zmq::sockopt::linger, 0);
  raw.connect(hub.endpoint());
  raw.send(zmq::str_buffer("\xff\xff\xff garbage"));
  EXPECT_THROW(hub.receive_from("fdm"), Error);
}

}  // namespace
}  // namespace mpfd::cosim
