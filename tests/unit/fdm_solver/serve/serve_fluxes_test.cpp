// Protocol v1.1 (proto/README.md §14) on fdm_solver serve: the FACES region's
// crossed_* amounts are the solver's own watched-face crossing bit for bit, and
// with the outflow_* of the cells below the face they account for every change
// of those cells; malformed FACES regions are refused at Setup.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numeric>

#include "common/config/scene_loader.hpp"
#include "fdm_solver/euler_solver.hpp"
#include "serve_harness.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

v1::Region faces_box(const std::string& name, int axis, std::initializer_list<long> lo,
                     std::initializer_list<long> hi,
                     std::initializer_list<const char*> quantities = {}) {
  v1::Region region = cell_box(name, lo, hi, quantities);
  region.set_kind(v1::REGION_KIND_FACES);
  region.set_face_axis(static_cast<std::uint32_t>(axis));
  return region;
}

constexpr int kFace = 57;  // between cells 56 and 57 of the 100-cell Sod tube: the shock crosses

TEST(FdmServeFluxes, CrossedAmountsAreTheSolversAndBalanceTheCellsBelowWithTheOutflow) {
  ServedFdm fdm;
  const auto ack = fdm.request(
      setup(sod_text(100),
            {faces_box("coupling_face", 0, {kFace}, {kFace + 1}),
             cell_box("below", {0}, {kFace}, {"rho", "E", "outflow_mass", "outflow_energy"})}));
  EXPECT_EQ(ack.header.setup_ack().regions(0).quantities_size(), 3);  // crossed_*
  const auto scene = config::parse_scene(sod_text(100), "sod.yaml");
  EulerSolver direct(scene, {.cfl = scene.time.fdm_cfl()});
  direct.watch_face(0, kFace);
  const auto sum = [](const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0);
  };
  const double volume = 0.01;  // 1 m^3 / 100 cells
  cosim::Message first;
  add_export(first, "below");
  const auto start = fdm.request(std::move(first));
  const double mass0 = sum(array_of(start, "below", "rho")) * volume;
  const double energy0 = sum(array_of(start, "below", "E")) * volume;
  double crossed_mass = 0, crossed_energy = 0, time = 0;
  cosim::Message reply;
  for (std::uint64_t step = 1; step <= 400; ++step) {
    const double dt = direct.stable_dt();
    fdm.hub().set_clock(step, time);
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    add_export(exchange, "coupling_face");
    add_export(exchange, "below");
    reply = fdm.request(std::move(exchange));
    direct.advance(dt);
    time += dt;
    const auto mass = array_of(reply, "coupling_face", "crossed_mass");
    const auto momentum = array_of(reply, "coupling_face", "crossed_momentum");
    ASSERT_EQ(mass.size(), 1U);
    ASSERT_EQ(momentum.size(), 3U);
    EXPECT_EQ(mass[0], direct.watched_crossing()[kDensity]) << step;
    EXPECT_EQ(momentum[0], direct.watched_crossing()[kMomentumX]) << step;
    direct.clear_watched_crossing();
    crossed_mass += mass[0];
    crossed_energy += array_of(reply, "coupling_face", "crossed_energy")[0];
  }
  const double mass = sum(array_of(reply, "below", "rho")) * volume;
  const double energy = sum(array_of(reply, "below", "E")) * volume;
  const double out_mass = array_of(reply, "below", "outflow_mass").at(0);
  const double out_energy = array_of(reply, "below", "outflow_energy").at(0);
  EXPECT_GT(crossed_mass, 0.05 * mass0);
  EXPECT_LT(out_mass, -1e-3 * mass0);  // the rarefaction draws gas in at x = 0
  EXPECT_NEAR((mass + crossed_mass + out_mass) / mass0, 1.0, 1e-13);
  EXPECT_NEAR((energy + crossed_energy + out_energy) / energy0, 1.0, 1e-13);
  // An export without an Advance in between hands over nothing new.
  cosim::Message again;
  add_export(again, "coupling_face");
  EXPECT_EQ(array_of(fdm.request(std::move(again)), "coupling_face", "crossed_mass").at(0), 0.0);
}

TEST(FdmServeFluxes, AFacesBoxOnADomainFaceIsRefusedNamingTheRule) {
  ServedFdm fdm;
  const auto text = fdm.refusal(setup(sod_text(100), {faces_box("face", 0, {0}, {1})}));
  EXPECT_THAT(text, AllOf(HasSubstr("ERROR_CODE_UNKNOWN_REGION"), HasSubstr("'face'"),
                          HasSubstr("faces between cells f - 1 and f")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("ERROR_CODE_UNKNOWN_REGION"));
}

// A face_axis past int's range (a bad peer) or an inactive axis is refused, not
// read as a negative index.
TEST(FdmServeFluxes, AFaceAxisOutOfRangeOrInactiveIsRefused) {
  for (const std::uint32_t axis : {0xFFFFFFFFu, 0x80000000u, 3u, 1u}) {
    ServedFdm fdm;
    auto region = faces_box("face", 0, {kFace}, {kFace + 1});
    region.set_face_axis(axis);
    const auto text = fdm.refusal(setup(sod_text(100), {region}));
    EXPECT_THAT(text, AllOf(HasSubstr("ERROR_CODE_UNKNOWN_REGION"),
                            HasSubstr("face_axis " + std::to_string(axis) + " is not an active")))
        << axis;
  }
}

TEST(FdmServeFluxes, CrossedAmountsOnACellsRegionAreRefused) {
  ServedFdm fdm;
  const auto text =
      fdm.refusal(setup(sod_text(100), {cell_box("cells", {4}, {6}, {"crossed_mass"})}));
  EXPECT_THAT(text, AllOf(HasSubstr("'crossed_mass'"), HasSubstr("belongs to FACES regions")));
  EXPECT_THAT(fdm.stop_reason(), HasSubstr("ERROR_CODE_UNKNOWN_REGION"));
}

}  // namespace
}  // namespace mpfd::fdm
