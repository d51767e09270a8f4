// `coupler replay` (coupler/run/replay.hpp) on the checked-in recording of a
// small CFDMP run (data/cfdmp_small.yaml, 37 steps, the shock crossing the zone
// face): each live solver gives back every recorded reply bit for bit, and a
// recording with one value changed is caught at that value.
#include "coupler/run/replay.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>

#include "cosim/codec.hpp"
#include "cosim/player.hpp"
#include "cosim/recorder.hpp"
#include "coupler/run/launch.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kRecording =
    std::filesystem::path(MPFD_TEST_DATA) / "cfdmp_small.mpfdrec";

/// ctest runs the tests of this file in parallel processes: each test writes
/// to its own folder.
ReplayOptions options_for(const std::string& solver) {
  ReplayOptions o;
  o.solver = solver;
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  o.out_dir = std::filesystem::temp_directory_path() / ("mpfd-replay-test-" + solver + "-" + test);
  return o;
}

TEST(Replay, Fdm_replies_match_the_recording_bit_for_bit) {
  const auto report = replay(kRecording, options_for("fdm"), embedded_serve("fdm"));
  EXPECT_FALSE(report.divergence) << *report.divergence;
  EXPECT_GT(report.requests, 37U);
  EXPECT_GT(report.values_compared, 600U);  // strip_cells (2 cells x 6 values) and audits
}

TEST(Replay, Mpm_replies_match_the_recording_bit_for_bit) {
  const auto report = replay(kRecording, options_for("mpm"), embedded_serve("mpm"));
  EXPECT_FALSE(report.divergence) << *report.divergence;
  EXPECT_GT(report.values_compared, 1000U);
}

TEST(Replay, A_changed_value_is_reported_by_step_field_and_index) {
  // Copy the recording, adding 1e-12 to strip_cells/rho[1] of the FDM's 10th Exchange reply.
  const auto tampered = std::filesystem::temp_directory_path() / "mpfd-replay-tampered.mpfdrec";
  {
    cosim::Player player(kRecording);
    cosim::Recorder recorder(tampered);
    int fdm_replies = 0;
    while (auto record = player.next()) {
      auto& message = record->message;
      if (record->peer == "fdm" && record->direction == cosim::v1::DIRECTION_RECEIVED &&
          message.header.has_exchange_result() && ++fdm_replies == 10) {
        for (const auto& array : message.header.arrays()) {
          if (array.group() != "strip_cells" || array.name() != "rho") continue;
          auto& frame = message.frames.at(array.frame_index());
          double value = 0;
          std::memcpy(&value, static_cast<char*>(frame.data()) + sizeof value, sizeof value);
          value += 1e-12;
          std::memcpy(static_cast<char*>(frame.data()) + sizeof value, &value, sizeof value);
        }
      }
      auto parts = cosim::encode(std::move(message));
      recorder.record(record->direction, record->peer, parts);
    }
    recorder.close();
  }
  const auto report = replay(tampered, options_for("fdm"), embedded_serve("fdm"));
  ASSERT_TRUE(report.divergence);
  EXPECT_THAT(*report.divergence, HasSubstr("step 9, exchange"));
  EXPECT_THAT(*report.divergence, HasSubstr("array strip_cells/rho index 1: recorded"));
  // Within a relative tolerance of 1e-9 the same replay passes.
  auto tolerant = options_for("fdm");
  tolerant.tolerance = 1e-9;
  EXPECT_FALSE(replay(tampered, tolerant, embedded_serve("fdm")).divergence);
}

}  // namespace
}  // namespace mpfd::coupler
