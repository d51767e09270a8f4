// Gauges of a coupled run (coupler/run/gauges.hpp): which solver owns a point,
// the SampleGauges operations a step carries, and the histories written from the replies.
#include "coupler/run/gauges.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "cosim/arrays.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::HasSubstr;

// A 1 m tube: FDM [0, 0.6], MPM [0.4, 1]; gauges at 0.2 (FDM), 0.5 (overlap: MPM), 0.9 (MPM).
std::string tube(const std::string& gauge_interval) {
  return "name: tube\ntime: {end: 1.0e-3}\n"
         "domain: {lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [40, 1, 1]}\n"
         "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
         "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
         "output: {interval: 1.0e-3" +
         gauge_interval +
         "}\nsolver: {method: cfdmp}\n"
         "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.6, 0.01, 0.01]}\n"
         "  mpm: {lower: [0.4, 0, 0], upper: [1, 0.01, 0.01]}\n"
         "gauges:\n  - {name: a, position: [0.2, 0.005, 0.005]}\n"
         "  - {name: b, position: [0.5, 0.005, 0.005]}\n"
         "  - {name: c, position: [0.9, 0.005, 0.005]}\n";
}

std::filesystem::path fresh_gauges_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpfd-coupler-gauges-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A reply of `ops` results whose last is SampleGauges of `n` gauges, pressures `p`
/// (density 1.5, a particle's position coordinates 0.25, every other quantity 7).
cosim::Message reply(int ops, const std::vector<std::string>& quantities,
                     const std::vector<double>& p) {
  cosim::Message m;
  auto& result = *m.header.mutable_exchange_result();
  for (int i = 0; i + 1 < ops; ++i) result.add_results()->mutable_proposed();
  result.add_results()->mutable_sampled()->set_count(p.size());
  for (const auto& q : quantities) {
    std::vector<double> values = p;
    const bool position = q.starts_with("position_");
    if (q != "pressure")
      for (auto& v : values) v = q == "rho" || q == "density" ? 1.5 : position ? 0.25 : 7.0;
    cosim::add_array(m, {"gauges", q, {}, ""}, std::move(values));
  }
  return m;
}

TEST(CoupledGauges, Each_point_belongs_to_the_solver_whose_zone_holds_it) {
  const auto scene = config::parse_scene(tube(""), "tube.yaml");
  EXPECT_EQ(gauge_owner(scene, scene.gauges[0]), "fdm");
  EXPECT_EQ(gauge_owner(scene, scene.gauges[1]), "mpm");  // the handshake belongs to the MPM
  EXPECT_EQ(gauge_owner(scene, scene.gauges[2]), "mpm");
  auto outside = scene;
  outside.zones->fdm->upper[0] = 0.3;
  outside.zones->mpm->lower[0] = 0.7;
  config::Gauge g{"gap", {0.5, 0.005, 0.005}};
  try {
    (void)gauge_owner(outside, g);
    FAIL() << "a gauge in neither zone was accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("gauge 'gap'"));
    EXPECT_THAT(e.what(), HasSubstr("neither zones.fdm nor zones.mpm"));
  }
}

TEST(CoupledGauges, A_step_asks_each_owner_and_the_histories_use_the_standalone_layout) {
  const auto scene = config::parse_scene(tube(""), "tube.yaml");
  const auto out = fresh_gauges_dir("every-step");
  CoupledGauges gauges(scene, out);
  cosim::Message fdm, mpm;
  fdm.header.mutable_exchange()->add_operations()->mutable_propose_dt();
  gauges.add(false, 0.0, GaugeSamplers::owners, fdm, mpm);  // step 0 samples t = 0
  ASSERT_EQ(fdm.header.exchange().operations_size(), 2);
  const auto& fdm_op = fdm.header.exchange().operations(1).sample();
  EXPECT_EQ(fdm_op.group(), "gauges");
  ASSERT_EQ(fdm_op.gauge_names_size(), 1);
  EXPECT_EQ(fdm_op.gauge_names(0), "a");
  ASSERT_EQ(fdm_op.positions_size(), 3);
  EXPECT_DOUBLE_EQ(fdm_op.positions(0), 0.2);
  EXPECT_EQ(fdm_op.quantities(0), "rho");  // the FDM's name of the density
  const auto& mpm_op = mpm.header.exchange().operations(0).sample();
  ASSERT_EQ(mpm_op.gauge_names_size(), 2);
  EXPECT_EQ(mpm_op.gauge_names(1), "c");
  EXPECT_EQ(mpm_op.quantities(0), "density");

  const std::vector<std::string> fq(fdm_op.quantities().begin(), fdm_op.quantities().end());
  const std::vector<std::string> mq(mpm_op.quantities().begin(), mpm_op.quantities().end());
  gauges.read(reply(2, fq, {1.0e5}), reply(1, mq, {2.0e5, 3.0e5}));
  // An exchange that does not advance (before an output) takes no sample.
  cosim::Message fdm2, mpm2;
  gauges.add(false, 0.0, GaugeSamplers::owners, fdm2, mpm2);
  EXPECT_EQ(fdm2.header.exchange().operations_size(), 0);
  gauges.read(fdm2, mpm2);
  cosim::Message fdm3, mpm3;
  gauges.add(true, 1.0e-4, GaugeSamplers::owners, fdm3, mpm3);
  gauges.read(reply(1, fq, {4.0e5}), reply(1, mq, {5.0e5, 6.0e5}));
  gauges.flush();
  EXPECT_EQ(gauges.sample_count(), 2u);

  std::ifstream csv(out / "gauges.csv");
  std::string header, first, second;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  EXPECT_THAT(header, HasSubstr("time[s],a.density[kg/m^3],a.pressure[Pa],a.velocity_x[m/s]"));
  EXPECT_THAT(header,
              HasSubstr("c.velocity_z[m/s],c.position_x[m],c.position_y[m],c.position_z[m]"));
  // a: the FDM's cell, recorded at the gauge's point; b, c: where the MPM read them.
  EXPECT_EQ(first,
            "0,1.5,100000,7,7,7,0.2,0.005,0.005,1.5,200000,7,7,7,0.25,0.25,0.25,"
            "1.5,300000,7,7,7,0.25,0.25,0.25");
  EXPECT_THAT(second, HasSubstr("0.0001,1.5,400000,"));
  EXPECT_TRUE(std::filesystem::exists(out / "gauges.h5"));
  const auto listing = gauges.listing();
  ASSERT_EQ(listing.size(), 3u);
  EXPECT_EQ(listing[1]["solver"], "mpm");
  EXPECT_EQ(listing[0]["solver"], "fdm");
}

// While the MPM zone sleeps the FDM runs its cells: it samples every gauge, and
// the sleeping MPM gets nothing.
TEST(CoupledGauges, The_FDM_samples_every_gauge_while_the_MPM_zone_sleeps) {
  const auto scene = config::parse_scene(tube(""), "tube.yaml");
  CoupledGauges gauges(scene, fresh_gauges_dir("dormant"));
  cosim::Message fdm, mpm;
  gauges.add(false, 0.0, GaugeSamplers::fdm_only_mpm_asleep, fdm, mpm);
  ASSERT_EQ(fdm.header.exchange().operations_size(), 1);
  EXPECT_EQ(mpm.header.exchange().operations_size(), 0);
  const auto& op = fdm.header.exchange().operations(0).sample();
  ASSERT_EQ(op.gauge_names_size(), 3);
  EXPECT_EQ(op.gauge_names(2), "c");
  const std::vector<std::string> fq(op.quantities().begin(), op.quantities().end());
  gauges.read(reply(1, fq, {1.0e5, 2.0e5, 3.0e5}), cosim::Message{});
  EXPECT_EQ(gauges.sample_count(), 1u);
}

// A gauge that follows the material (T §3.4.4) is the MPM's in every phase: the
// idle MPM of AFDMP's phase 2 samples it beside the FDM; a sleeping CFDMP zone
// and the 1D stage cannot, and it records NaN.
TEST(CoupledGauges, A_following_gauge_is_sampled_by_the_MPM_or_recorded_as_NaN) {
  std::string text = tube("");
  text.replace(text.find("[0.9, 0.005, 0.005]}"), 20, "[0.9, 0.005, 0.005], follow: material}");
  const auto scene = config::parse_scene(text, "tube.yaml");
  EXPECT_EQ(gauge_owner(scene, scene.gauges[2]), "mpm");
  const auto out = fresh_gauges_dir("following");
  CoupledGauges gauges(scene, out);
  EXPECT_EQ(gauges.listing()[2]["follow"], "material");
  EXPECT_EQ(gauges.listing()[0]["follow"], "point");

  cosim::Message fdm, mpm;
  gauges.add(false, 0.0, GaugeSamplers::fdm_only, fdm, mpm);
  ASSERT_EQ(fdm.header.exchange().operations_size(), 1);
  ASSERT_EQ(mpm.header.exchange().operations_size(), 1);
  const auto& fop = fdm.header.exchange().operations(0).sample();
  const auto& mop = mpm.header.exchange().operations(0).sample();
  ASSERT_EQ(fop.gauge_names_size(), 2);
  ASSERT_EQ(mop.gauge_names_size(), 1);
  EXPECT_EQ(mop.gauge_names(0), "c");
  const std::vector<std::string> fq(fop.quantities().begin(), fop.quantities().end());
  const std::vector<std::string> mq(mop.quantities().begin(), mop.quantities().end());
  gauges.read(reply(1, fq, {1.0e5, 2.0e5}), reply(1, mq, {3.0e5}));

  cosim::Message fdm2, mpm2;
  gauges.add(true, 1.0e-4, GaugeSamplers::fdm_only_mpm_asleep, fdm2, mpm2);
  EXPECT_EQ(mpm2.header.exchange().operations_size(), 0);
  gauges.read(reply(1, fq, {4.0e5, 5.0e5}), cosim::Message{});
  gauges.record_pressure(2.0e-4, std::vector<double>{6.0e5, 7.0e5, 8.0e5});
  gauges.flush();
  std::ifstream csv(out / "gauges.csv");
  std::string header, first, second, third;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  std::getline(csv, third);
  EXPECT_EQ(first,
            "0,1.5,100000,7,7,7,0.2,0.005,0.005,1.5,200000,7,7,7,0.5,0.005,0.005,"
            "1.5,300000,7,7,7,0.25,0.25,0.25");
  EXPECT_EQ(second,
            "0.0001,1.5,400000,7,7,7,0.2,0.005,0.005,1.5,500000,7,7,7,0.5,0.005,0.005,"
            "nan,nan,nan,nan,nan,nan,nan,nan");
  EXPECT_EQ(third,
            "0.0002,nan,600000,nan,nan,nan,0.2,0.005,0.005,nan,700000,nan,nan,nan,0.5,0.005,0.005,"
            "nan,nan,nan,nan,nan,nan,nan,nan");
}

// AFDMP's phases 1 and 3 run the MPM over the whole domain: it samples every gauge.
TEST(CoupledGauges, The_MPM_samples_every_gauge_in_an_MPM_phase) {
  const auto scene = config::parse_scene(tube(""), "tube.yaml");
  CoupledGauges gauges(scene, fresh_gauges_dir("mpm-phase"));
  cosim::Message fdm, mpm;
  gauges.add(false, 0.0, GaugeSamplers::mpm_only, fdm, mpm);
  EXPECT_EQ(fdm.header.exchange().operations_size(), 0);
  ASSERT_EQ(mpm.header.exchange().operations_size(), 1);
  const auto& op = mpm.header.exchange().operations(0).sample();
  ASSERT_EQ(op.gauge_names_size(), 3);
  const std::vector<std::string> mq(op.quantities().begin(), op.quantities().end());
  gauges.read(cosim::Message{}, reply(1, mq, {1.0e5, 2.0e5, 3.0e5}));
  EXPECT_EQ(gauges.sample_count(), 1u);
}

// AFDMP's 1D spherical start knows pressure only; it records it on the same schedule.
TEST(CoupledGauges, A_stage_without_solvers_records_pressure_when_due) {
  const auto scene = config::parse_scene(tube(", gauge_interval: 1.0e-4"), "tube.yaml");
  const auto out = fresh_gauges_dir("pressure-only");
  CoupledGauges gauges(scene, out);
  const std::vector<double> p = {1.0e5, 2.0e5, 3.0e5};
  for (int n = 0; n <= 10; ++n)
    if (gauges.due(0.3e-4 * n)) gauges.record_pressure(0.3e-4 * n, p);
  EXPECT_EQ(gauges.sample_count(), 4u);
  EXPECT_THROW(gauges.record_pressure(1.0, std::vector<double>{1.0}), Error);
}

// V5 (T Figs. 3.12-3.14): a scene with a structure records its Mises stress,
// which the MPM samples; the FDM's fluid has none (0).
TEST(CoupledGauges, A_scene_with_a_structure_records_the_MPM_s_Mises_stress) {
  auto scene = config::parse_scene(tube(""), "tube.yaml");
  config::Material steel;
  steel.name = "steel";
  steel.strength = config::ElasticStrength{};
  scene.materials.push_back(steel);
  const auto out = fresh_gauges_dir("mises");
  CoupledGauges gauges(scene, out);
  cosim::Message fdm, mpm;
  gauges.add(false, 0.0, GaugeSamplers::owners, fdm, mpm);
  const auto& mop = mpm.header.exchange().operations(0).sample();
  const std::vector<std::string> mq(mop.quantities().begin(), mop.quantities().end());
  ASSERT_EQ(mq.size(), 9u);
  EXPECT_EQ(mq[5], "mises_stress");
  EXPECT_EQ(mq[8], "position_z");
  const auto& fop = fdm.header.exchange().operations(0).sample();
  const std::vector<std::string> fq(fop.quantities().begin(), fop.quantities().end());
  EXPECT_EQ(fq.size(), 5u);
  gauges.read(reply(1, fq, {1.0e5}), reply(1, mq, {2.0e5, 3.0e5}));
  gauges.flush();
  std::ifstream csv(out / "gauges.csv");
  std::string header, row;
  std::getline(csv, header);
  std::getline(csv, row);
  EXPECT_THAT(header, HasSubstr("c.mises_stress[Pa]"));
  EXPECT_THAT(header, HasSubstr("a.mises_stress[Pa]"));
  EXPECT_THAT(header, HasSubstr("a.mises_stress[Pa],a.position_x[m]"));
  // a (FDM): 0 and its point; c (MPM): the reply's values (7, and its particle at 0.25).
  EXPECT_THAT(row, HasSubstr(",7,7,7,0,0.2,0.005,0.005,"));
  EXPECT_THAT(row, HasSubstr(",7,7,7,7,0.25,0.25,0.25"));
}

TEST(CoupledGauges, Samples_follow_the_gauge_interval) {
  const auto scene = config::parse_scene(tube(", gauge_interval: 1.0e-4"), "tube.yaml");
  CoupledGauges gauges(scene, fresh_gauges_dir("interval"));
  int sampled = 0;
  // Steps of 0.3e-4 s: samples at 0, then at the first step end past 1e-4, 2e-4, ...
  for (int n = 0; n <= 10; ++n) {
    cosim::Message fdm, mpm;
    gauges.add(n > 0, 0.3e-4 * n, GaugeSamplers::owners, fdm, mpm);
    if (fdm.header.exchange().operations_size() > 0) ++sampled;
  }
  // t = 0, 1.2e-4, 2.1e-4, 3.0e-4 (3e-4 reached within round-off).
  EXPECT_EQ(sampled, 4);
}

TEST(CoupledGauges, A_scene_without_gauges_writes_no_file_and_asks_nothing) {
  auto scene = config::parse_scene(tube(""), "tube.yaml");
  scene.gauges.clear();
  const auto out = fresh_gauges_dir("none");
  CoupledGauges gauges(scene, out);
  cosim::Message fdm, mpm;
  gauges.add(false, 0.0, GaugeSamplers::owners, fdm, mpm);
  EXPECT_EQ(fdm.header.exchange().operations_size(), 0);
  EXPECT_EQ(mpm.header.exchange().operations_size(), 0);
  gauges.flush();
  EXPECT_FALSE(std::filesystem::exists(out / "gauges.csv"));
}

}  // namespace
}  // namespace mpfd::coupler
