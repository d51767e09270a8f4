#include "cosim/recorder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"
#include "cosim/hub.hpp"
#include "cosim/player.hpp"
#include "echo_solver.hpp"
#include "test_endpoints.hpp"

namespace mpfd::cosim {
namespace {

constexpr int steps = 5;

std::filesystem::path temp_file(const std::string& name) {
  return std::filesystem::temp_directory_path() /
         ("mpfd-" + std::to_string(::getpid()) + "-" + name + ".mpfdrec");
}

/// Runs hello, `steps` exchanges with one echo solver and shutdown, recording at the hub.
void record_session(const std::filesystem::path& path) {
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::inproc));
  Recorder recorder(path);
  hub.attach_recorder(&recorder);
  testing::SolverThread solver([&] {
    Participant participant(context, hub.endpoint(), "fdm");
    participant.connect(v1::Hello{});
    testing::serve_echo(participant);
  });
  const std::vector<std::string> peers{"fdm"};
  hub.accept(peers, "run-rec");
  for (int step = 1; step <= steps; ++step) {
    hub.set_clock(static_cast<std::uint64_t>(step), 0.0);
    Message request;
    auto* exchange = request.header.mutable_exchange();
    exchange->add_operations()->mutable_apply()->set_region("strip");
    exchange->add_operations()->mutable_export_region()->set_region("strip");
    add_array(request, {"strip", "rho", {}, "kg/m^3"},
              std::vector<double>(10000, static_cast<double>(step)));
    hub.send("fdm", std::move(request));
    hub.receive_from("fdm");
  }
  Message shutdown;
  shutdown.header.mutable_shutdown();
  hub.send("fdm", std::move(shutdown));
  hub.receive_from("fdm");
  solver.join_and_rethrow();
  recorder.close();
  EXPECT_EQ(recorder.records_written(), 2U * (steps + 2));
}

TEST(Recorder, PlayerReadsBackEveryMessageInOrderWithItsFrames) {
  const auto path = temp_file("roundtrip");
  record_session(path);
  Player player(path);
  bool has_message_proto = false;
  for (const auto& file : player.schema().file()) {
    has_message_proto |= file.name() == "mpfd/cosim/v1/message.proto";
  }
  EXPECT_TRUE(has_message_proto);
  std::vector<RecordedMessage> records;
  while (auto record = player.next()) records.push_back(std::move(*record));
  ASSERT_EQ(records.size(), 2U * (steps + 2));
  EXPECT_EQ(records[0].direction, v1::DIRECTION_RECEIVED);
  EXPECT_TRUE(records[0].message.header.has_hello());
  EXPECT_TRUE(records[1].message.header.has_hello_ack());
  const auto& last_reply = records[2 * steps + 1].message;
  EXPECT_EQ(last_reply.header.envelope().step(), static_cast<std::uint64_t>(steps));
  EXPECT_EQ(view_array<double>(last_reply, "strip", "rho").values()[9999], 2.0 * steps);
  EXPECT_EQ(records.back().peer, "fdm");
  EXPECT_LE(records[2].timestamp_ns, records[3].timestamp_ns);
  std::filesystem::remove(path);
}

TEST(Recorder, TruncatedRecordingIsAnErrorWithTheByteOffset) {
  const auto path = temp_file("truncated");
  record_session(path);
  std::filesystem::resize_file(path, std::filesystem::file_size(path) - 100);
  Player player(path);
  try {
    while (player.next()) {
    }
    FAIL() << "a truncated recording was read to the end";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("is corrupt at byte"), std::string::npos)
        << error.what();
  }
  std::filesystem::remove(path);
}

TEST(Recorder, FileWithoutTheMagicIsRejected) {
  const auto path = temp_file("magic");
  std::ofstream(path) << "definitely not a recording";
  try {
    Player player(path);
    FAIL() << "bad magic accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("bad magic"), std::string::npos) << error.what();
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace mpfd::cosim
