// The watch over what the coupler's deposits take from the FDM cells beside the
// coupling face (coupler/run/face_drain.hpp).
#include "coupler/run/face_drain.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace mpfd::coupler {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

constexpr double kCellVolume = 2.0e-3;  // m^3

/// Two deposits: the first takes 0.9 of face cell 3's 1 kg/m^3, the second 0.1 of
/// face cell `second`'s (0.5 taken back, 0.4 brought by particles, per m^3).
void deposit_twice(FaceDrainWatch& watch, std::size_t second) {
  watch.start_deposit();
  watch.observe(3, 1.0, -0.9, -0.9 * kCellVolume, kCellVolume);
  watch.start_deposit();
  watch.observe(second, 1.0, -0.1, -0.5 * kCellVolume, kCellVolume);
}

TEST(FaceDrainWatch, Keeps_the_face_cell_the_last_deposit_took_the_largest_share_of) {
  FaceDrainWatch watch;
  watch.start_deposit();
  // Cell 0 gains; cell 1 loses 0.2 of its 1 kg/m^3 (0.3 taken back, 0.1 brought
  // by particles, per m^3); cell 2 loses 0.6 of its 0.5 kg/m^3, nothing brought.
  watch.observe(0, 1.0, +0.4, 0.0, kCellVolume);
  watch.observe(1, 1.0, -0.2, -0.3 * kCellVolume, kCellVolume);
  watch.observe(2, 0.5, -0.3, -0.3 * kCellVolume, kCellVolume);
  EXPECT_EQ(watch.last().face_cell, 2u);
  EXPECT_DOUBLE_EQ(watch.last().share, 0.6);
  EXPECT_DOUBLE_EQ(watch.last().density, 0.5);
  EXPECT_DOUBLE_EQ(watch.last().taken_back, 0.3 * kCellVolume);
  EXPECT_DOUBLE_EQ(watch.last().particle_mass, 0.0);
  EXPECT_DOUBLE_EQ(watch.run_max_share(), 0.6);
}

// The FDM, or the coupler's strip checks, find an emptied cell in the step after the
// deposit (or after an output's exchange without advance): the deposit before the
// last still counts.
TEST(FaceDrainWatch, The_last_two_deposits_count_and_the_run_keeps_its_largest_share) {
  FaceDrainWatch watch;
  deposit_twice(watch, 3);
  EXPECT_DOUBLE_EQ(watch.last().share, 0.1);
  EXPECT_NEAR(watch.last().particle_mass, 0.4 * kCellVolume, 1e-18);
  EXPECT_DOUBLE_EQ(watch.worst().share, 0.9);
  EXPECT_NE(watch.cause_text("(3, 0, 0)"), "");
  watch.start_deposit();
  EXPECT_DOUBLE_EQ(watch.worst().share, 0.1);
  EXPECT_EQ(watch.cause_text("(3, 0, 0)"), "");
  EXPECT_DOUBLE_EQ(watch.run_max_share(), 0.9);
}

// A restarted run's watch (its checkpoint keeps the last two deposits' worst cells):
// an error in the first step after the restart names the cause the run would have.
TEST(FaceDrainWatch, A_resumed_watch_names_the_cause_as_the_watch_it_was_saved_from) {
  FaceDrainWatch running;
  deposit_twice(running, 4);
  FaceDrainWatch resumed;
  resumed.resume(running.last(), running.previous(), running.run_max_share());
  EXPECT_EQ(resumed.worst().face_cell, 3u);
  EXPECT_NE(resumed.cause_text("(3, 0, 0)"), "");
  EXPECT_EQ(resumed.cause_text("(3, 0, 0)"), running.cause_text("(3, 0, 0)"));
  resumed.start_deposit();  // the deposit before the last goes, as in the running watch
  running.start_deposit();
  EXPECT_EQ(resumed.cause_text("(4, 0, 0)"), running.cause_text("(4, 0, 0)"));
  EXPECT_DOUBLE_EQ(resumed.run_max_share(), 0.9);
}

TEST(FaceDrainWatch, Names_the_cause_only_from_half_the_cells_mass_on) {
  FaceDrainWatch watch;
  watch.start_deposit();
  watch.observe(0, 1.0, -0.49, -0.49 * kCellVolume, kCellVolume);
  EXPECT_EQ(watch.cause_text("(18, 4, 0)"), "");
  watch.start_deposit();
  watch.observe(0, 1.0, -0.5, -0.5 * kCellVolume, kCellVolume);
  EXPECT_NE(watch.cause_text("(18, 4, 0)"), "");
  watch.start_deposit();
  watch.observe(0, 0.411, -0.415, -0.415 * kCellVolume, kCellVolume);
  EXPECT_THAT(watch.cause_text("(18, 4, 0) at (1.17, 0.285, 0.0317) m"),
              AllOf(HasSubstr("Cause: a deposit of the coupler took 101 % of the mass of FDM cell "
                              "(18, 4, 0) at (1.17, 0.285, "
                              "0.0317) m beside the coupling face (density 0.411 kg/m^3"),
                    HasSubstr("0.00083 kg, is taken back"),
                    HasSubstr("the particles that crossed brought 0 kg"),
                    HasSubstr("move the zone face (zones.mpm)")));
}

TEST(FaceDrainWatch, An_empty_or_unset_cell_is_not_a_share) {
  FaceDrainWatch watch;
  watch.start_deposit();
  watch.observe(0, 0.0, -1.0, -1.0 * kCellVolume, kCellVolume);
  EXPECT_DOUBLE_EQ(watch.last().share, 0.0);
  EXPECT_EQ(watch.cause_text("(0, 0, 0)"), "");
}

}  // namespace
}  // namespace mpfd::coupler
