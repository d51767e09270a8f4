// The zone clock both solvers' checkpoints keep (cosim/serving/checkpoint_clock.hpp):
// read back as written, and refused, naming the file and both values, for another
// step, another Setup start time, or a start time that is not finite (it would
// become the restored zone's clock).
#include "cosim/serving/checkpoint_clock.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "cosim/serving/protocol_error.hpp"

namespace mpfd::cosim {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;

class CheckpointClockTest : public ::testing::Test {
 protected:
  /// A file holding `clock` alone.
  fs::path written(const CheckpointClock& clock, const std::string& name) {
    const fs::path file = dir_ / (name + ".h5");
    io::Hdf5File h5(file, io::Hdf5File::Mode::create);
    write_checkpoint_clock(h5, clock);
    return file;
  }

  std::string refusal(const fs::path& file, std::uint64_t step, double setup_start_time) {
    try {
      (void)read_checkpoint_clock(CheckpointReader(file), step, setup_start_time);
    } catch (const ProtocolError& error) {
      EXPECT_FALSE(error.fatal()) << "a refused Restore leaves the zone serving";
      return error.what();
    }
    return "no error";
  }

  void SetUp() override {
    // One folder per test: ctest runs them in parallel.
    dir_ = fs::temp_directory_path() /
           (std::string("mpfd-checkpoint-clock-") +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
  // A zone set up at 1 ms whose import moved its clock to 2.5 ms, 40 steps on.
  const CheckpointClock moved_{
      .steps = 40, .solver_time = 3.0e-4, .start_time = 2.5e-3, .setup_start_time = 1.0e-3};
};

TEST_F(CheckpointClockTest, A_moved_clock_reads_back_as_written) {
  const auto file = written(moved_, "moved");
  const CheckpointClock back = read_checkpoint_clock(CheckpointReader(file), 40, 1.0e-3);
  EXPECT_EQ(back.steps, 40);
  EXPECT_EQ(back.solver_time, 3.0e-4);
  EXPECT_EQ(back.start_time, 2.5e-3);
  EXPECT_EQ(back.setup_start_time, 1.0e-3);
  EXPECT_EQ(io::Hdf5File(file, io::Hdf5File::Mode::read).read_attribute("/", "time"),
            2.5e-3 + 3.0e-4);
}

TEST_F(CheckpointClockTest, Another_step_or_setup_start_time_is_refused_naming_both) {
  const auto file = written(moved_, "moved");
  EXPECT_THAT(refusal(file, 41, 1.0e-3),
              AllOf(HasSubstr(file.string()), HasSubstr("was taken at step 40"),
                    HasSubstr("the Restore request says step 41")));
  EXPECT_THAT(refusal(file, 40, 0.0),
              AllOf(HasSubstr("set up with start_time 0.001 s"), HasSubstr("Setup gave 0 s")));
}

TEST_F(CheckpointClockTest, A_start_time_that_is_not_finite_is_refused) {
  for (const double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    CheckpointClock clock = moved_;
    clock.start_time = bad;
    const auto file = written(clock, "bad");
    EXPECT_THAT(
        refusal(file, 40, 1.0e-3),
        AllOf(HasSubstr(file.string()), HasSubstr("has start_time"), HasSubstr("must be finite")))
        << bad;
    fs::remove(file);
  }
}

}  // namespace
}  // namespace mpfd::cosim
