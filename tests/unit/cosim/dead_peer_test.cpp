// A peer that dies or hangs mid-run is reported, naming it, within the timeout.

#include <gtest/gtest.h>

#include "common/core/error.hpp"
#include "cosim/hub.hpp"
#include "echo_solver.hpp"
#include "test_endpoints.hpp"

namespace mpfd::cosim {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr milliseconds reply_timeout{500};
// Allowed lateness beyond the timeout: thread scheduling on a loaded 2-core machine.
constexpr milliseconds margin{1000};

TransportOptions short_timeouts() {
  TransportOptions options;
  options.reply_timeout = reply_timeout;
  options.idle_timeout = reply_timeout;
  return options;
}

Message request_dt() {
  Message message;
  message.header.mutable_exchange()->add_operations()->mutable_propose_dt();
  return message;
}

class DeadPeer : public ::testing::TestWithParam<Transport> {};

TEST_P(DeadPeer, SolverThatExitsAfterHelloIsReportedByNameWithinTheTimeout) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(GetParam()), short_timeouts());
  testing::SolverThread solver([&] {
    Participant participant(context, hub.endpoint(), "mpm", short_timeouts());
    participant.connect(v1::Hello{});
    participant.receive();  // the first request arrives, then the solver dies without answering
  });
  const std::vector<std::string> peers{"mpm"};
  hub.accept(peers, "run-dead");
  hub.send("mpm", request_dt());
  solver.join_and_rethrow();
  const auto start = Clock::now();
  try {
    hub.send("mpm", request_dt());
    hub.receive_from("mpm");
    hub.receive_from("mpm");
    FAIL() << "a dead solver went unnoticed";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("solver 'mpm'"), std::string::npos) << error.what();
  }
  EXPECT_LT(Clock::now() - start, reply_timeout + margin);
}

INSTANTIATE_TEST_SUITE_P(Transports, DeadPeer,
                         ::testing::Values(Transport::inproc, Transport::ipc, Transport::tcp),
                         testing::transport_test_name);

TEST(DeadPeer, HungSolverTimesOutWithItsNameEndpointAndTimeout) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::tcp), short_timeouts());
  std::atomic<bool> release{false};
  testing::SolverThread solver([&] {
    Participant participant(context, hub.endpoint(), "fdm", short_timeouts());
    participant.connect(v1::Hello{});
    participant.receive();
    while (!release) std::this_thread::sleep_for(milliseconds{10});
  });
  const std::vector<std::string> peers{"fdm"};
  hub.accept(peers, "run-hung");
  hub.send("fdm", request_dt());
  const auto start = Clock::now();
  try {
    hub.receive_from("fdm");
    FAIL() << "a hung solver went unnoticed";
  } catch (const Error& error) {
    const std::string text = error.what();
    EXPECT_NE(text.find("solver 'fdm' at tcp://127.0.0.1:"), std::string::npos) << text;
    EXPECT_NE(text.find("did not answer within 0.5 s"), std::string::npos) << text;
  }
  const auto waited = Clock::now() - start;
  EXPECT_GE(waited, reply_timeout - milliseconds{50});
  EXPECT_LT(waited, reply_timeout + margin);
  release = true;
  solver.join_and_rethrow();
}

TEST(DeadPeer, SolverReportsACouplerThatStoppedSending) {
  zmq::context_t context;
  auto hub = std::make_unique<Hub>(context, testing::unique_bind_endpoint(Transport::ipc),
                                   short_timeouts());
  Participant participant(context, hub->endpoint(), "fdm", short_timeouts());
  testing::SolverThread coupler([&] {
    const std::vector<std::string> peers{"fdm"};
    hub->accept(peers, "run-gone");
    hub.reset();
  });
  participant.connect(v1::Hello{});
  coupler.join_and_rethrow();
  const auto start = Clock::now();
  try {
    participant.receive();
    FAIL() << "a silent coupler went unnoticed";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("solver 'fdm': coupler at ipc://"), std::string::npos)
        << error.what();
  }
  EXPECT_LT(Clock::now() - start, reply_timeout + margin);
}

TEST(DeadPeer, ALongAnswerArrivesWithinAPerCallTimeoutLongerThanTheReplyTimeout) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::inproc), short_timeouts());
  testing::SolverThread solver([&] {
    Participant participant(context, hub.endpoint(), "fdm", short_timeouts());
    participant.connect(v1::Hello{});
    const Message request = participant.receive();
    std::this_thread::sleep_for(3 * reply_timeout);  // a whole-field commit, say
    Message done;
    done.header.mutable_field_import_done()->set_transfer_id("h1");
    participant.reply(request, std::move(done));
    participant.receive();  // the Shutdown
  });
  const std::vector<std::string> peers{"fdm"};
  hub.accept(peers, "run-long");
  hub.send("fdm", request_dt());
  const Message reply = hub.receive_from("fdm", 10 * reply_timeout);
  EXPECT_EQ(reply.header.field_import_done().transfer_id(), "h1");
  Message shutdown;
  shutdown.header.mutable_shutdown();
  hub.send("fdm", std::move(shutdown));
  solver.join_and_rethrow();
}

}  // namespace
}  // namespace mpfd::cosim
