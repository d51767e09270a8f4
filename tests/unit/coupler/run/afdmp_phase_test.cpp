// The AFDMP phase machine (coupler/run/afdmp_phase.hpp, design §3.3): tables
// of observations -> phases.
#include "coupler/run/afdmp_phase.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "common/core/error.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::HasSubstr;

PhaseSettings fsi_scene(AfdmpStart start) {
  PhaseSettings s;
  s.start = start;
  s.end_time = 3e-4;
  s.fsi_zone = true;
  s.activation_pressure = 2.0e5;
  s.handoff_radius = 0.04;
  return s;
}

Observation at(double t) {
  Observation o;
  o.time = t;
  return o;
}

Observation charge(double t, std::size_t explosive, bool complete) {
  Observation o;
  o.time = t;
  o.charge_burn = BurnObservation{explosive, complete};
  return o;
}

Observation watch(double t, std::vector<double> pressure) {
  Observation o;
  o.time = t;
  o.watch_pressure = std::move(pressure);
  return o;
}

TEST(PhaseMachine, MpmStartRunsDetonationThenBlastThenFsi) {
  PhaseMachine m(fsi_scene(AfdmpStart::mpm));
  EXPECT_EQ(m.phase(), AfdmpPhase::mpm_detonation);
  EXPECT_FALSE(m.next(charge(0.0, 100, false)));
  EXPECT_FALSE(m.next(charge(2e-6, 100, false)));
  const auto h1 = m.next(charge(7.4e-6, 100, true));
  ASSERT_TRUE(h1);
  EXPECT_EQ(h1->from, AfdmpPhase::mpm_detonation);
  EXPECT_EQ(h1->to, AfdmpPhase::fdm_blast);
  EXPECT_EQ(h1->trigger, AfdmpTrigger::burn_complete);
  EXPECT_EQ(h1->time, 7.4e-6);
  EXPECT_EQ(h1->value, 100.0);
  EXPECT_FALSE(m.next(watch(1e-5, {1e5, 1.9e5})));
  EXPECT_FALSE(m.next(watch(2e-5, {1e5, 2.0e5})));  // passes means above (as CFDMP's watch)
  const auto h2 = m.next(watch(3e-5, {2.1e5, 1.5e5}));
  ASSERT_TRUE(h2);
  EXPECT_EQ(h2->to, AfdmpPhase::mpm_fsi);
  EXPECT_EQ(h2->trigger, AfdmpTrigger::pressure);
  EXPECT_EQ(h2->value, 2.1e5);
  EXPECT_EQ(h2->threshold, 2.0e5);
  EXPECT_EQ(h2->summary()["trigger"], "pressure");
  EXPECT_FALSE(m.next(at(1e-4)));  // phase 3 needs no input and has no trigger
  const auto end = m.next(at(3e-4));
  ASSERT_TRUE(end);
  EXPECT_EQ(end->from, AfdmpPhase::mpm_fsi);
  EXPECT_EQ(end->trigger, AfdmpTrigger::end_time);
  EXPECT_EQ(m.phase(), AfdmpPhase::done);
  EXPECT_FALSE(m.next(at(4e-4)));
}

TEST(PhaseMachine, SphericalStartNeedsTheBurnAndTheFrontAtTheHandoffRadius) {
  PhaseMachine m(fsi_scene(AfdmpStart::spherical));
  EXPECT_EQ(m.phase(), AfdmpPhase::spherical_detonation);
  const auto one_d = [](double t, bool burnt, double front) {
    Observation o;
    o.time = t;
    o.spherical_burn_complete = burnt;
    o.front_radius = front;
    return o;
  };
  EXPECT_FALSE(m.next(one_d(1e-6, false, 0.05)));  // front past, burn not done
  EXPECT_FALSE(m.next(one_d(2e-6, true, 0.039)));
  const auto h = m.next(one_d(3e-6, true, 0.041));
  ASSERT_TRUE(h);
  EXPECT_EQ(h->to, AfdmpPhase::fdm_blast);
  EXPECT_EQ(h->trigger, AfdmpTrigger::front_radius);
  EXPECT_EQ(h->threshold, 0.04);
}

TEST(PhaseMachine, EndTimeEndsEveryPhaseAndWinsOverATrigger) {
  for (const AfdmpStart start : {AfdmpStart::mpm, AfdmpStart::spherical}) {
    PhaseMachine m(fsi_scene(start));
    Observation o = charge(3e-4 * (1 - 1e-13), 10, true);  // within the loop's landing tolerance
    o.spherical_burn_complete = true;
    o.front_radius = 1.0;
    const auto t = m.next(o);
    ASSERT_TRUE(t);
    EXPECT_EQ(t->to, AfdmpPhase::done);
    EXPECT_EQ(t->trigger, AfdmpTrigger::end_time);
  }
  PhaseMachine blast(fsi_scene(AfdmpStart::mpm));
  ASSERT_TRUE(blast.next(charge(0.0, 10, true)));
  const auto t = blast.next(watch(3e-4, {1e9}));
  ASSERT_TRUE(t);
  EXPECT_EQ(t->from, AfdmpPhase::fdm_blast);
  EXPECT_EQ(t->to, AfdmpPhase::done);
}

TEST(PhaseMachine, WithoutFsiZoneTheBlastRunsToTheEnd) {
  PhaseSettings s = fsi_scene(AfdmpStart::mpm);
  s.fsi_zone = false;
  s.activation_pressure.reset();
  PhaseMachine m(s);
  ASSERT_TRUE(m.next(charge(5e-6, 10, true)));
  EXPECT_FALSE(m.next(at(1e-4)));  // no watch input needed
  EXPECT_FALSE(m.next(watch(2e-4, {1e12})));
  EXPECT_EQ(m.phase(), AfdmpPhase::fdm_blast);
  ASSERT_TRUE(m.next(at(3e-4)));
  EXPECT_EQ(m.phase(), AfdmpPhase::done);
}

TEST(PhaseMachine, TriggerAtStepZeroHandsOffAtTimeZero) {
  PhaseMachine m(fsi_scene(AfdmpStart::mpm));
  const auto h1 = m.next(charge(0.0, 10, true));  // instantaneous burn
  ASSERT_TRUE(h1);
  EXPECT_EQ(h1->time, 0.0);
  const auto h2 = m.next(watch(0.0, {1.0e5 + 1.0}));
  EXPECT_FALSE(h2);  // 1e5 Pa ambient is below 2e5
  PhaseSettings low = fsi_scene(AfdmpStart::mpm);
  low.activation_pressure = 0.9e5;  // below ambient
  PhaseMachine n(low);
  ASSERT_TRUE(n.next(charge(0.0, 10, true)));
  const auto at_once = n.next(watch(0.0, {1.0e5}));
  ASSERT_TRUE(at_once);
  EXPECT_EQ(at_once->to, AfdmpPhase::mpm_fsi);
  EXPECT_EQ(at_once->time, 0.0);
}

// An unlit particle pushed out of the charge box would make the box's
// check vacuously true: with fewer explosive particles than at step 0 the
// machine reads the fluid_particles export.
TEST(PhaseMachine, BurnCheckMovesToTheFluidExportWhenTheChargeBoxLosesParticles) {
  PhaseMachine m(fsi_scene(AfdmpStart::mpm));
  EXPECT_FALSE(m.next(charge(0.0, 100, false)));
  EXPECT_FALSE(m.needs_fluid_burn_check({100, false}));
  EXPECT_TRUE(m.needs_fluid_burn_check({99, true}));
  Observation o = charge(1e-6, 99, true);
  EXPECT_THAT(
      [&] {
        try {
          (void)m.next(o);
        } catch (const Error& e) {
          return std::string(e.what());
        }
        return std::string("no error");
      }(),
      HasSubstr("lacks the fluid_particles burn state"));
  o.fluid_burn = BurnObservation{100, false};
  EXPECT_FALSE(m.next(o));
  o.fluid_burn = BurnObservation{100, true};
  o.time = 2e-6;
  ASSERT_TRUE(m.next(o));
}

TEST(PhaseMachine, RefusesMissingInputsAndSettings) {
  PhaseMachine m(fsi_scene(AfdmpStart::mpm));
  EXPECT_THROW((void)m.next(at(1e-6)), Error);
  PhaseSettings no_threshold = fsi_scene(AfdmpStart::mpm);
  no_threshold.activation_pressure.reset();
  EXPECT_THROW(PhaseMachine{no_threshold}, Error);
  PhaseSettings no_radius = fsi_scene(AfdmpStart::spherical);
  no_radius.handoff_radius = 0.0;
  EXPECT_THROW(PhaseMachine{no_radius}, Error);
}

}  // namespace
}  // namespace mpfd::coupler
