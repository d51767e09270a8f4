// `mpm_solver serve` stepped by a coupler gives the same particles, bit for
// bit, as MpmSolver advanced directly with the same dt, over inproc and ipc;
// exports between steps do not disturb the step; WriteOutput and Shutdown.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/followed_gauges.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::mpm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// cfdmp_regions() and "all": every particle of the grid.
std::vector<v1::Region> regions_with_all_core_arrays() {
  auto regions = cfdmp_regions();
  regions.push_back(region("all", v1::REGION_KIND_PARTICLES, {0, 0, 0}, {16, 16, 1},
                           {"id", "position", "velocity", "mass", "internal_energy"}));
  return regions;
}

class ServeTransport : public ::testing::TestWithParam<cosim::Transport> {};

TEST_P(ServeTransport, TwentyStepsGiveTheDirectSolversParticlesBitForBit) {
  ServedMpm served(GetParam());
  const auto ack =
      served.request(setup(blast_text(), regions_with_all_core_arrays())).header.setup_ack();
  ASSERT_EQ(ack.regions_size(), 4);
  EXPECT_EQ(ack.regions(0).quantities_size(), 3);

  const auto scene = config::parse_scene(blast_text(), "blast.yaml");
  MpmSolver direct(scene, MpmSettings::from_scene(scene));
  EXPECT_EQ(ack.stable_dt(), direct.stable_dt());
  double dt = ack.stable_dt();
  double time = 0.0;
  cosim::Message last;
  for (std::uint64_t step = 1; step <= 20; ++step) {
    served.hub().set_clock(step, time);
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    add_export(exchange, "ghost_nodes");  // maps particles to nodes between steps
    add_export(exchange, "all");
    add_propose(exchange);
    last = served.request(std::move(exchange));
    direct.advance(dt);
    time += dt;
    const auto& results = last.header.exchange_result().results();
    ASSERT_EQ(results.size(), 4);
    EXPECT_EQ(results[0].advanced().time(), time);
    EXPECT_EQ(results[3].proposed().stable_dt(), direct.stable_dt());
    dt = results[3].proposed().stable_dt();
  }
  const ParticleSet& ps = direct.particles();
  const auto position = array_of(last, "all", "position");
  const auto velocity = array_of(last, "all", "velocity");
  const auto id = array_of<std::uint64_t>(last, "all", "id");
  ASSERT_EQ(id.size(), ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p) {
    ASSERT_EQ(id[p], ps.id[p]);
    for (std::size_t a = 0; a < 3; ++a) {
      ASSERT_EQ(position[3 * p + a], ps.position[a][p]) << "particle " << p;
      ASSERT_EQ(velocity[3 * p + a], ps.velocity[a][p]) << "particle " << p;
    }
  }
  // Nodal mass of the ghost nodes: the direct solver's (2-12) at the same state.
  direct.map_particles_to_nodes();
  const auto mass = array_of(last, "ghost_nodes", "mass");
  ASSERT_EQ(mass.size(), 3U * 17U);
  double total = 0.0;
  for (int i = 3; i < 6; ++i)
    for (int j = 0; j < 17; ++j) {
      const double m = mass[static_cast<std::size_t>((i - 3) * 17 + j)];
      EXPECT_EQ(m, direct.node_state({i, j, 0}).mass);
      total += m;
    }
  EXPECT_GT(total, 0.0);  // particles have spread past x = 0.25
  EXPECT_EQ(served.shut_down().steps_done(), 20U);
  EXPECT_EQ(served.stop_reason(), "");
}

INSTANTIATE_TEST_SUITE_P(InprocAndIpc, ServeTransport,
                         ::testing::Values(cosim::Transport::inproc, cosim::Transport::ipc));

TEST(MpmServe, WriteOutputWritesAParticleSnapshotIntoTheOutputDir) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("mpfd-mpm-serve-output-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ServedMpm served;
  const double dt =
      served.request(setup(blast_text(), {}, dir.string())).header.setup_ack().stable_dt();
  cosim::Message exchange;
  add_advance(exchange, dt, 0.0);
  served.request(std::move(exchange));
  cosim::Message output;
  output.header.mutable_write_output();
  const auto written = served.request(std::move(output)).header.output_written();
  ASSERT_EQ(written.files_size(), 2);
  EXPECT_TRUE(std::filesystem::is_regular_file(written.files(0))) << written.files(0);
  EXPECT_TRUE(std::filesystem::is_regular_file(dir / "particles.xmf"));
  served.shut_down();
  std::filesystem::remove_all(dir);
}

TEST(MpmServe, GaugesReadTheNearestParticle) {
  ServedMpm served;
  served.request(setup(blast_text(), {}));
  cosim::Message exchange;
  auto& sample = *add_op(exchange).mutable_sample();
  sample.set_group("gauges");
  for (const char* name : {"core", "air"}) sample.add_gauge_names(name);
  for (const double x : {0.5, 0.5, 0.03, 0.3, 0.1, 0.03}) sample.add_positions(x);
  for (const char* q : {"density", "pressure"}) sample.add_quantities(q);
  const auto reply = served.request(std::move(exchange));
  EXPECT_EQ(reply.header.exchange_result().results(0).sampled().count(), 2U);
  // blast_text: the core holds 2 kg/m^3 at 1 MPa, the air 1 kg/m^3 at 0.1 MPa.
  EXPECT_EQ(array_of(reply, "gauges", "density"), (std::vector<double>{2.0, 1.0}));
  const auto pressure = array_of(reply, "gauges", "pressure");
  EXPECT_NEAR(pressure[0], 1.0e6, 1e-6);
  EXPECT_NEAR(pressure[1], 1.0e5, 1e-7);
}

TEST(MpmServe, AFollowingGaugeReadsTheParticleBoundAtSetupAsTheDirectSolver) {
  // A gauge on the core's edge, where the blast moves the particles outward,
  // and a fixed one at the same point.
  const std::string text =
      blast_text() +
      "gauges:\n  - {name: edge, position: [0.38, 0.5, 0.03], follow: material}\n"
      "  - {name: fixed, position: [0.38, 0.5, 0.03]}\n";
  ServedMpm served;
  double dt = served.request(setup(text, {})).header.setup_ack().stable_dt();
  const auto scene = config::parse_scene(text, "blast.yaml");
  MpmSolver direct(scene, MpmSettings::from_scene(scene));
  FollowedGauges followed(scene.gauges, direct.particles(), binding_reach(direct.grid()));
  const double x0 = direct.particles().position[0][followed.particle("edge", direct.particles())];
  double time = 0.0;
  const std::vector<std::string> quantities = {"position_x", "position_y", "velocity_x",
                                               "pressure"};
  cosim::Message last;
  for (std::uint64_t step = 1; step <= 10; ++step) {
    served.hub().set_clock(step, time);
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    auto& sample = *add_op(exchange).mutable_sample();
    sample.set_group("gauges");
    for (const char* name : {"edge", "fixed"}) sample.add_gauge_names(name);
    for (int g = 0; g < 2; ++g)
      for (const double x : {0.38, 0.5, 0.03}) sample.add_positions(x);
    for (const auto& q : quantities) sample.add_quantities(q);
    add_propose(exchange);
    last = served.request(std::move(exchange));
    direct.advance(dt);
    time += dt;
    dt = last.header.exchange_result().results(2).proposed().stable_dt();
  }
  const ParticleSet& ps = direct.particles();
  const std::size_t p = followed.particle("edge", ps);
  const std::size_t q = nearest_particle(ps, {0.38, 0.5, 0.03});
  const auto x = array_of(last, "gauges", "position_x");
  const auto y = array_of(last, "gauges", "position_y");
  const auto vx = array_of(last, "gauges", "velocity_x");
  const auto pressure = array_of(last, "gauges", "pressure");
  EXPECT_EQ((std::vector<double>{x[0], y[0], vx[0], pressure[0]}),
            (std::vector<double>{ps.position[0][p], ps.position[1][p], ps.velocity[0][p],
                                 ps.pressure[p]}));
  EXPECT_EQ((std::vector<double>{x[1], y[1], vx[1], pressure[1]}),
            (std::vector<double>{ps.position[0][q], ps.position[1][q], ps.velocity[0][q],
                                 ps.pressure[q]}));
  EXPECT_LT(vx[0], 0.0);  // the core's left edge expands toward -x
  EXPECT_LT(x[0], x0);    // and the gauge went with it
}

TEST(MpmServe, SetupRefusesAFollowingGaugeWithNoParticleWithinOneCell) {
  ServedMpm served;
  // The particles fill x in [0.25, 0.75): none within a cell (0.0625 m) of x = 0.1.
  EXPECT_THAT(
      served.refusal(setup(
          blast_text() + "gauges: [{name: far, position: [0.1, 0.5, 0.03], follow: material}]\n",
          {})),
      AllOf(HasSubstr("gauge 'far' at (0.1, 0.5, 0.03) m follows the material"),
            HasSubstr("expected one within one cell (0.0625 m)")));
  EXPECT_THAT(served.stop_reason(), HasSubstr("MALFORMED"));
}

TEST(MpmServe, ADormantZoneRefusesAnExchangeUntilActivated) {
  ServedMpm served;
  served.request(setup(blast_text(), {}, "", true));
  cosim::Message activate;
  activate.header.mutable_activate()->set_reason("test");
  EXPECT_GT(served.request(std::move(activate)).header.activate_ack().stable_dt(), 0.0);
  cosim::Message exchange;
  add_propose(exchange);
  EXPECT_GT(served.request(std::move(exchange))
                .header.exchange_result()
                .results(0)
                .proposed()
                .stable_dt(),
            0.0);
  served.shut_down();

  ServedMpm asleep;
  asleep.request(setup(blast_text(), {}, "", true));
  cosim::Message early;
  add_propose(early);
  EXPECT_NE(asleep.refusal(std::move(early)).find("dormant"), std::string::npos);
  EXPECT_NE(asleep.stop_reason().find("UNEXPECTED"), std::string::npos);
}

TEST(MpmServe, AZoneWokenAtTimeTStartsItsClockThere) {
  ServedMpm served;
  served.request(setup(blast_text(), {}, "", true));
  served.hub().set_clock(7, 2.5e-3);  // the coupler's t^n at the switch
  cosim::Message activate;
  activate.header.mutable_activate()->set_reason("test");
  served.request(std::move(activate));
  cosim::Message from_zero;
  add_advance(from_zero, 1e-7, 0.0);
  EXPECT_NE(served.refusal(std::move(from_zero)).find("solver is at 0.0025 s"), std::string::npos);
  EXPECT_NE(served.stop_reason().find("UNEXPECTED"), std::string::npos);

  ServedMpm woken;
  woken.request(setup(blast_text(), {}, "", true));
  woken.hub().set_clock(7, 2.5e-3);
  cosim::Message wake;
  wake.header.mutable_activate()->set_reason("test");
  woken.request(std::move(wake));
  cosim::Message step;
  add_advance(step, 1e-7, 2.5e-3);
  const auto reply = woken.request(std::move(step));
  EXPECT_DOUBLE_EQ(reply.header.exchange_result().results(0).advanced().time(), 2.5e-3 + 1e-7);
}

}  // namespace
}  // namespace mpfd::mpm
