// Checkpoint and Restore of fdm_solver serve (proto/README.md §8): a restored
// solver continues bit for bit; files from another grid and multi-material
// zones are refused by name, and the solver carries on.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "fdm_solver/serve/sha256.hpp"
#include "serve_harness.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// dt of every step: Sod's tube with 100 cells stays at CFL ~0.12 (|u| + c < 1.3 m/s, dx 0.01 m).
constexpr double kDt = 1e-3;

/// A fresh temporary folder, removed at the end of the test.
class TempDir {
 public:
  explicit TempDir(const std::string& tag)
      : path_(std::filesystem::temp_directory_path() /
              ("mpfd-fdm-checkpoint-" + tag + "-" + std::to_string(::getpid()))) {
    std::filesystem::remove_all(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

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

cosim::Message checkpoint_to(const std::string& path) {
  cosim::Message message;
  message.header.mutable_checkpoint()->set_path(path);
  return message;
}

cosim::Message restore_from(const std::string& path, std::uint64_t step) {
  cosim::Message message;
  message.header.mutable_restore()->set_path(path);
  message.header.mutable_restore()->set_step(step);
  return message;
}

/// Sod's tube whose left state is a second ideal gas (gamma 5/3): two materials, so tracers.
std::string two_gas_sod_text(int n) {
  std::string text = sod_text(n);
  const std::string gas = "  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n";
  text.replace(text.find(gas), gas.size(),
               gas + "  heavy: {eos: {type: ideal_gas, gamma: 1.6666666666666667}}\n");
  const std::string left = "{name: left, material: gas";
  text.replace(text.find(left), left.size(), "{name: left, material: heavy");
  return text;
}

TEST(FdmServeCheckpoint, Sha256OfAbcIsTheFips180Example) {
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  // 56 bytes: the padding needs a second block (FIPS 180-2 appendix B.2).
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
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
  EXPECT_EQ(written.sha256(), sha256_hex_of_file(file));
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

TEST(FdmServeCheckpoint,
     CheckpointOfTwoMaterialsIsRefusedNamingTheTracerLimitationAndWritesNothing) {
  const TempDir dir("two");
  ServedFdm fdm;
  fdm.request(setup(two_gas_sod_text(20), {}, dir.path().string()));
  EXPECT_THAT(fdm.refusal(checkpoint_to("")),
              AllOf(HasSubstr("ERROR_CODE_UNEXPECTED"), HasSubstr("2 materials"),
                    HasSubstr("multi-material (tracer) state is not restorable")));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "checkpoints"));
  EXPECT_EQ(advance(fdm, 0.0, 1), kDt);  // non-fatal: the solver carries on
}

}  // namespace
}  // namespace mpfd::fdm
