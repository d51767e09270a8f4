// A Restore from a checkpoint that does not fit the running two-material zone
// (another grid, another material count, a truncated or altered file, a
// missing digest, another step) is refused: a non-fatal Error{IO} naming the
// file and what mismatched, the zone's whole state (cells, clock, tracers)
// untouched, so that it continues as its twin that was never asked to restore.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "checkpoint_support.hpp"
#include "cosim/serving/protocol_error.hpp"
#include "cosim/serving/sha256.hpp"
#include "fdm_solver/serve/checkpoint.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

/// A checkpoint of `scene` after `steps` steps, written into the folder `dir`; its path.
fs::path checkpoint_of(const std::string& scene, int steps, const fs::path& dir) {
  const auto zone = zone_of(scene, dir);
  advance_stable(*zone, steps);
  fs::create_directories(dir);  // a folder: the checkpoint is checkpoint_NNNNNN.h5 in it
  cosim::v1::Checkpoint request;
  request.set_path(dir.string());
  return write_checkpoint(*zone, request).path();
}

/// A copy of `file` (and of its digest beside it) called `name`.
fs::path copy_of(const fs::path& file, const std::string& name) {
  const fs::path copy = file.parent_path() / name;
  fs::copy_file(file, copy, fs::copy_options::overwrite_existing);
  fs::copy_file(file.string() + ".sha256", copy.string() + ".sha256",
                fs::copy_options::overwrite_existing);
  return copy;
}

/// Rewrites the digest beside `file` to match it as it is now.
void redigest(const fs::path& file) {
  std::ofstream(file.string() + ".sha256")
      << cosim::sha256_hex_of_file(file) << "  " << file.filename().string() << '\n';
}

class FdmCheckpointRefusal : public ::testing::Test {
 protected:
  static constexpr int kStepsTaken = 3;
  FdmCheckpointRefusal()
      : dir_("refusal"),
        zone_(zone_of(corner_charge_text(20, 20))),
        twin_(zone_of(corner_charge_text(20, 20))) {
    advance_stable(*zone_, kStepsTaken);
    advance_stable(*twin_, kStepsTaken);
    good_ = checkpoint_of(corner_charge_text(20, 20), 12, dir_.path() / "good");
  }

  /// The refusal of restoring `file` at `step`: its text, once it is checked to be non-fatal IO.
  std::string refusal(const fs::path& file, std::uint64_t step = 12) {
    const SolverImage before(zone_->solver);
    cosim::v1::Restore request;
    request.set_path(file.string());
    request.set_step(step);
    std::string text = "(no error: the restore was done)";
    try {
      (void)restore_checkpoint(*zone_, request);
    } catch (const cosim::ProtocolError& error) {
      EXPECT_EQ(error.code(), cosim::v1::ERROR_CODE_IO);
      EXPECT_FALSE(error.fatal());
      text = error.what();
    }
    EXPECT_TRUE(SolverImage(zone_->solver) == before) << "the refused restore changed the state";
    return text;
  }

  TempDir dir_;
  std::unique_ptr<ServedZone> zone_, twin_;
  fs::path good_;
};

TEST_F(FdmCheckpointRefusal, AnotherGridIsNamedWithBothCellCounts) {
  const fs::path file = checkpoint_of(corner_charge_text(16, 20), 12, dir_.path() / "grid");
  EXPECT_THAT(refusal(file), AllOf(HasSubstr(file.string()), HasSubstr("[16, 20, 1]"),
                                   HasSubstr("'corner_charge' has [20, 20, 1]")));
}

TEST_F(FdmCheckpointRefusal, AnotherMaterialCountIsNamedWithBothMaterialLists) {
  const fs::path file = checkpoint_of(corner_charge_text(20, 20, false), 12, dir_.path() / "air");
  EXPECT_THAT(refusal(file),
              AllOf(HasSubstr(file.string()), HasSubstr("holds material count 1 (air)"),
                    HasSubstr("has 2 (air, products)")));
}

TEST_F(FdmCheckpointRefusal, ATruncatedFileFailsItsDigestAndWithAMatchingDigestItsHdf5Read) {
  const fs::path file = copy_of(good_, "truncated.h5");
  fs::resize_file(file, fs::file_size(file) / 2);
  EXPECT_THAT(refusal(file), AllOf(HasSubstr(file.string()), HasSubstr("has SHA-256"),
                                   HasSubstr(file.string() + ".sha256' records"),
                                   HasSubstr("truncated or corrupt")));
  redigest(file);  // as if the file had been truncated before its digest was taken
  EXPECT_THAT(refusal(file),
              AllOf(HasSubstr("Restore from '" + file.string() + "' failed"), HasSubstr("HDF5")));
}

TEST_F(FdmCheckpointRefusal, AFlippedByteFailsTheDigest) {
  const fs::path file = copy_of(good_, "flipped.h5");
  {
    std::fstream bytes(file, std::ios::in | std::ios::out | std::ios::binary);
    bytes.seekg(static_cast<std::streamoff>(fs::file_size(file) / 2));
    const char c = static_cast<char>(bytes.get());
    bytes.seekp(static_cast<std::streamoff>(fs::file_size(file) / 2));
    bytes.put(static_cast<char>(c ^ 0x01));
  }
  EXPECT_THAT(refusal(file), AllOf(HasSubstr(file.string()), HasSubstr("has SHA-256"),
                                   HasSubstr("records " + cosim::sha256_hex_of_file(good_))));
}

TEST_F(FdmCheckpointRefusal, AFileWithoutItsDigestIsNotRead) {
  const fs::path file = copy_of(good_, "alone.h5");
  fs::remove(file.string() + ".sha256");
  EXPECT_THAT(refusal(file), AllOf(HasSubstr(file.string()), HasSubstr("has no readable")));
}

TEST_F(FdmCheckpointRefusal, AZoneSetUpAtAnotherStartTimeIsNamedWithBoth) {
  const fs::path folder = dir_.path() / "late";
  auto message = setup(corner_charge_text(20, 20), {}, folder.string());
  message.header.mutable_setup()->set_start_time(1e-3);
  const auto late = set_up_zone(message.header.setup());
  advance_stable(*late, 12);
  fs::create_directories(folder);
  cosim::v1::Checkpoint request;
  request.set_path(folder.string());
  const fs::path file = write_checkpoint(*late, request).path();
  EXPECT_THAT(refusal(file), AllOf(HasSubstr(file.string()),
                                   HasSubstr("set up with start_time 0.001 s; Setup gave 0 s")));
}

TEST_F(FdmCheckpointRefusal, AnotherStepIsNamedWithBoth) {
  EXPECT_THAT(refusal(good_, 13),
              AllOf(HasSubstr(good_.string()), HasSubstr("was taken at step 12"),
                    HasSubstr("the Restore request says step 13")));
}

TEST_F(FdmCheckpointRefusal, AfterEveryRefusalTheZoneContinuesAsItsTwinBitwise) {
  const fs::path grid = checkpoint_of(corner_charge_text(16, 20), 12, dir_.path() / "grid");
  const fs::path air = checkpoint_of(corner_charge_text(20, 20, false), 12, dir_.path() / "air");
  const fs::path truncated = copy_of(good_, "truncated.h5");
  fs::resize_file(truncated, fs::file_size(truncated) / 2);
  redigest(truncated);
  for (const fs::path& file : {grid, air, truncated})
    EXPECT_THAT(refusal(file), HasSubstr("Restore"));
  EXPECT_THAT(refusal(good_, 11), HasSubstr("step"));
  advance_stable(*zone_, 5);
  advance_stable(*twin_, 5);
  EXPECT_TRUE(SolverImage(zone_->solver) == SolverImage(twin_->solver));
  EXPECT_EQ(zone_->solver.steps(), kStepsTaken + 5);
}

}  // namespace
}  // namespace mpfd::fdm
