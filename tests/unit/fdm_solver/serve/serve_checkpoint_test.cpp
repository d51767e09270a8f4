// Checkpoint and Restore of fdm_solver serve (proto/README.md §8): a restored
// solver, one- or two-material, continues bit for bit; a file from another
// grid is refused by name, and the solver carries on; a Restore that fails
// after it replaced the state stops the solver.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "checkpoint_support.hpp"
#include "cosim/serving/sha256.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// dt of every step: Sod's tube with 100 cells stays at CFL ~0.12 (|u| + c < 1.3 m/s, dx 0.01 m).
constexpr double kDt = 1e-3;

/// Advances `steps` steps of kDt from `time`, one Exchange each; the time reached.
double advance(ServedFdm& fdm, double time, int steps) {
  for (int s = 0; s < steps; ++s) {
    cosim::Message exchange;
    add_advance(exchange, kDt, time);
    fdm.request(std::move(exchange));
    time += kDt;
  }
  return time;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// rho, momentum and E of region "tube", one after the other.
std::vector<double> exported_state(ServedFdm& fdm) {
  cosim::Message exchange;
  add_export(exchange, "tube");
  const auto reply = fdm.request(std::move(exchange));
  std::vector<double> all;
  for (const char* q : {"rho", "momentum", "E"}) {
    const auto values = array_of(reply, "tube", q);
    all.insert(all.end(), values.begin(), values.end());
  }
  return all;
}

TEST(FdmServeCheckpoint, Sha256OfAbcIsTheFips180Example) {
  EXPECT_EQ(cosim::sha256_hex("abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // 56 bytes: the padding needs a second block (FIPS 180-2 appendix B.2).
  EXPECT_EQ(cosim::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(FdmServeCheckpoint, Sha256OfAFileIsHashedInPiecesAsTheWholeInMemory) {
  // FIPS 180-2 appendix B.3: a million 'a'.
  EXPECT_EQ(cosim::sha256_hex(std::string(1000000, 'a')),
            "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
  // A file of 2.5 MiB + 7 bytes: read in 1 MiB pieces, the last one short of a block.
  const TempDir dir("sha");
  std::string bytes(5 * (std::size_t{1} << 19) + 7, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 7919) % 251);
  std::filesystem::create_directories(dir.path());
  const auto file = dir.path() / "bytes.bin";
  std::ofstream(file, std::ios::binary) << bytes;
  EXPECT_EQ(cosim::sha256_hex_of_file(file), cosim::sha256_hex(bytes));
}

TEST(FdmServeCheckpoint,
     SodRestoredFromStepTenAndAdvancedTenStepsEqualsTheUninterruptedRunBitwise) {
  const TempDir dir("sod");
  const std::string scene = sod_text(100);
  const auto tube = cell_box("tube", {0}, {100}, {"rho", "momentum", "E"});

  ServedFdm first;
  first.request(setup(scene, {tube}, dir.path().string()));
  const double t10 = advance(first, 0.0, 10);
  const auto written = first.request(checkpoint_to("")).header.checkpoint_written();
  const auto file = dir.path() / "checkpoints" / "checkpoint_000010.h5";
  EXPECT_EQ(written.path(), file.string());
  EXPECT_EQ(written.bytes(), std::filesystem::file_size(file));
  EXPECT_EQ(written.sha256(), cosim::sha256_hex_of_file(file));
  EXPECT_EQ(written.step(), 10U);  // what Restore must name
  const double t20 = advance(first, t10, 10);
  const auto uninterrupted = exported_state(first);

  ServedFdm second;
  second.request(setup(scene, {tube}));
  const auto restored = second.request(restore_from(file.string(), 10)).header.restored();
  EXPECT_EQ(restored.step(), 10U);
  EXPECT_EQ(restored.time(), t10);
  EXPECT_GT(restored.stable_dt(), 0.0);
  EXPECT_EQ(advance(second, t10, 10), t20);
  const auto resumed = exported_state(second);
  ASSERT_EQ(resumed.size(), 500U);  // rho, 3 momentum components and E of 100 cells
  EXPECT_EQ(resumed, uninterrupted);
  second.shut_down();
  EXPECT_EQ(second.last_shutdown().steps_done(), 20U);
}

TEST(FdmServeCheckpoint, ARestoredZoneNumbersItsSnapshotsOnAndListsTheEarlierOnes) {
  const TempDir dir("series");
  const std::string scene = sod_text(20);
  const auto write_output = [](ServedFdm& fdm) {
    cosim::Message message;
    message.header.mutable_write_output();
    return fdm.request(std::move(message)).header.output_written().files(0);
  };
  ServedFdm first;
  first.request(setup(scene, {}, dir.path().string()));
  write_output(first);
  const double t1 = advance(first, 0.0, 1);
  write_output(first);
  const std::string file = first.request(checkpoint_to("")).header.checkpoint_written().path();
  advance(first, t1, 1);
  const std::string third = write_output(first);
  const std::string series = read_text(dir.path() / "cells.xmf");
  first.shut_down();

  // A zone restored in the same folder writes the third snapshot again, not the first.
  ServedFdm second;
  second.request(setup(scene, {}, dir.path().string()));
  second.request(restore_from(file, 1));
  advance(second, t1, 1);
  EXPECT_EQ(write_output(second), third);
  EXPECT_THAT(third, HasSubstr("snapshot_000002.h5"));
  EXPECT_EQ(read_text(dir.path() / "cells.xmf"), series);  // all three, with their times
}

TEST(FdmServeCheckpoint, RestoreOfAFileFromAnotherGridNamesTheFileAndBothCellCounts) {
  const TempDir dir("grid");
  ServedFdm twenty;
  twenty.request(setup(sod_text(20), {}, dir.path().string()));
  const std::string file = twenty.request(checkpoint_to("")).header.checkpoint_written().path();

  ServedFdm thirty;
  thirty.request(setup(sod_text(30), {}));
  EXPECT_THAT(thirty.refusal(restore_from(file, 0)),
              AllOf(HasSubstr("ERROR_CODE_IO"), HasSubstr(file), HasSubstr("[20, 1, 1]"),
                    HasSubstr("[30, 1, 1]")));
  // Non-fatal: the solver carries on from its own state.
  EXPECT_EQ(advance(thirty, 0.0, 1), kDt);
  thirty.shut_down();
  EXPECT_EQ(thirty.last_shutdown().steps_done(), 1U);
}

// The snapshot series resumes after the state is restored; where it cannot
// (a file stands where the snapshots folder goes), the zone holds the
// checkpoint's cells with its Setup's snapshot state: fatal, not a refusal.
TEST(FdmServeCheckpoint, ARestoreThatFailsAfterReplacingTheStateStopsTheSolver) {
  const TempDir dir("half");
  const auto first_dir = dir.path() / "first", second_dir = dir.path() / "second";
  ServedFdm first;
  first.request(setup(sod_text(20), {}, first_dir.string()));
  cosim::Message output;
  output.header.mutable_write_output();
  first.request(std::move(output));
  const std::string file = first.request(checkpoint_to("")).header.checkpoint_written().path();
  first.shut_down();

  std::filesystem::create_directories(second_dir);
  std::ofstream(second_dir / "snapshots") << "not a folder";
  ServedFdm second;
  second.request(setup(sod_text(20), {}, second_dir.string()));
  EXPECT_THAT(second.refusal(restore_from(file, 0)),
              AllOf(HasSubstr("failed after the state was replaced"),
                    HasSubstr("neither its Setup's nor the checkpoint's")));
  EXPECT_THAT(second.stop_reason(), HasSubstr("ERROR_CODE_IO"));
}

TEST(FdmServeCheckpoint,
     TwoMaterialZoneRestoredOverTheProtocolContinuesWithTheSameCellsAndPressures) {
  const TempDir dir("two");
  const std::string scene = corner_charge_text(20, 20);
  const auto all = cell_box("all", {0, 0}, {20, 20}, {"rho", "momentum", "E", "pressure"});
  constexpr double dt = 1e-6;  // below the stable 1.5e-6 s of steps 1-20
  const auto advance_by = [&](ServedFdm& fdm, double time, int steps) {
    for (int s = 0; s < steps; ++s, time += dt) {
      cosim::Message exchange;
      add_advance(exchange, dt, time);
      fdm.request(std::move(exchange));
    }
    return time;
  };
  const auto exported = [](ServedFdm& fdm) {
    cosim::Message exchange;
    add_export(exchange, "all");
    const auto reply = fdm.request(std::move(exchange));
    std::vector<double> values;
    for (const char* q : {"rho", "momentum", "E", "pressure"}) {
      const auto part = array_of(reply, "all", q);
      values.insert(values.end(), part.begin(), part.end());
    }
    return values;
  };

  ServedFdm first;
  first.request(setup(scene, {all}, dir.path().string()));
  const double t12 = advance_by(first, 0.0, 12);
  const auto written = first.request(checkpoint_to("")).header.checkpoint_written();
  EXPECT_EQ(written.sha256(), cosim::sha256_hex_of_file(written.path()));
  advance_by(first, t12, 8);
  const auto uninterrupted = exported(first);

  ServedFdm second;
  second.request(setup(scene, {all}));
  EXPECT_EQ(second.request(restore_from(written.path(), 12)).header.restored().step(), 12U);
  advance_by(second, t12, 8);
  const auto resumed = exported(second);
  ASSERT_EQ(resumed.size(), 400U * 6);  // rho, 3 momentum components, E and p of 400 cells
  EXPECT_EQ(resumed, uninterrupted);
}

}  // namespace
}  // namespace mpfd::fdm
