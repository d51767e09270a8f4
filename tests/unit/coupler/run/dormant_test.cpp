// The dormant FSI zone (coupler/run/activation.hpp, zones.mpm.activation_pressure):
// the real `fdm_solver serve` in a thread and a still-air stand-in for the MPM
// that counts the requests it gets after Setup.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "common/config/scene_loader.hpp"
#include "common/io/hdf5_file.hpp"
#include "common/io/output_directory.hpp"
#include "coupler/run/coupled_run.hpp"
#include "fdm_solver/serve/serve.hpp"
#include "tests/unit/coupler/run/still_mpm.hpp"

namespace mpfd::coupler {
namespace {

// Air in a closed 1 m tube of 40 cells, FDM [0, 0.6], MPM [0.4, 1], w = 5 cells;
// `pulse`: the first 0.25 m at 1.5e5 Pa (else 1e5 Pa everywhere), density 1.2.
std::string tube(double threshold, bool pulse, double end = 1.0e-3) {
  std::string text = testing::still_tube_scene(
      "dormant_tube", end, ", activation_pressure: " + std::to_string(threshold));
  if (pulse)
    text +=
        "bodies:\n  - {name: pulse, material: air, density: 1.2, pressure: 1.5e5,\n"
        "     shape: {box: {lower: [0, 0, 0], upper: [0.25, 0.01, 0.01]}}}\n";
  return text;
}

void serve_dormant_fdm(zmq::context_t& context, const std::string& endpoint,
                       const std::string& name) {
  fdm::serve(
      context,
      {.endpoint = endpoint, .name = name, .idle_timeout = std::chrono::milliseconds(10000)});
}

testing::StillMpm* g_dormant_mpm =
    nullptr;  // the stand-in a thread serves (ServeFunction has no state)
void serve_dormant_mpm(zmq::context_t& context, const std::string& endpoint, const std::string&) {
  testing::serve_still_mpm(context, endpoint, *g_dormant_mpm);
}

struct Run {
  nlohmann::json summary;
  std::filesystem::path out;
  CoupledRunReport report;
};

Run run(const std::string& text, testing::StillMpm& mpm, const std::string& name,
        std::chrono::milliseconds keep_alive = std::chrono::milliseconds(1000)) {
  mpm.cell_volume = 0.025 * 0.01 * 0.01;
  g_dormant_mpm = &mpm;
  zmq::context_t context;
  cosim::Hub hub(context, "inproc://coupler-dormant-test", {});
  const auto scene = config::parse_scene(text, name + ".yaml");
  std::vector<std::unique_ptr<SolverHandle>> solvers;
  solvers.push_back(start_thread("fdm", serve_dormant_fdm, context, hub.endpoint()));
  solvers.push_back(start_thread("mpm", serve_dormant_mpm, context, hub.endpoint()));
  Run result;
  result.out = std::filesystem::temp_directory_path() / ("mpfd-coupler-dormant-" + name);
  std::filesystem::remove_all(result.out);
  io::prepare_output_directory(result.out, false);
  CoupledRunOptions options;
  options.out_dir = result.out;
  options.progress = false;
  options.keep_alive = keep_alive;
  result.report = run_cfdmp(scene, text, hub, solvers, options);
  std::ifstream in(result.out / "summary.json");
  result.summary = nlohmann::json::parse(in);
  return result;
}

TEST(Dormant, A_zone_that_never_wakes_gets_no_message_after_setup) {
  testing::StillMpm mpm;
  const auto r = run(tube(2.0e5, false), mpm, "quiet");
  EXPECT_EQ(mpm.requests_after_setup.load(), 0);  // Shutdown aside
  const auto& activation = r.summary["details"]["activation"];
  EXPECT_EQ(activation["activated"], false);
  EXPECT_EQ(activation["threshold_pa"], 2.0e5);
  EXPECT_DOUBLE_EQ(activation["peak_strip_pressure_pa"].get<double>(), 1.0e5);
  EXPECT_DOUBLE_EQ(r.report.time, 1.0e-3);
  // Still air: the audit counts the FDM's cells of the whole tube, exact.
  EXPECT_EQ(r.report.mass_error, 0.0);
  EXPECT_EQ(r.report.energy_error, 0.0);
  EXPECT_NEAR(r.summary["details"]["zones"]["mpm"]["mass"].get<double>(), 24 * 1.2 * 2.5e-6, 1e-15);
  EXPECT_FALSE(std::filesystem::exists(r.out / "mpm" / "snapshots"));
}

TEST(Dormant, Pings_keep_a_sleeping_solver_past_its_idle_timeout) {
  testing::StillMpm mpm;
  mpm.idle_timeout_ms = 150;
  // ~41000 FDM-only steps of 73 us: 0.7 ... 3 s of wall time (three idle timeouts or
  // more), no request to the MPM; Pings every 25 ms, six to an idle timeout.
  const auto r = run(tube(2.0e5, false, 3.0), mpm, "long", std::chrono::milliseconds(25));
  EXPECT_GT(r.report.wall_seconds, 3 * 0.150);
  EXPECT_EQ(mpm.requests_after_setup.load(), 0);
  EXPECT_TRUE(mpm.shut_down.load());  // still serving at the end (without the Pings: not)
}

TEST(Dormant, While_asleep_the_fdm_cells_of_the_zone_keep_their_state_until_the_wave_comes) {
  testing::StillMpm mpm;
  const auto r = run(tube(1.0e6, true), mpm, "pulse");
  EXPECT_EQ(mpm.requests_after_setup.load(), 0);
  // At t = 1 ms the front (c = 342 m/s) has gone ~0.35 m past x = 0.25: the FDM
  // computed the zone's cells [0.4, 1) itself, with no ghost cells set (cells 24-26,
  // the ghost layers of an awake zone, carry the pulse, not the stand-in's still air).
  // Ahead of the front the cells hold the initial state but for the scheme's own
  // precursor, which falls ~3x per cell (measured: 6.5e-6 relative at cell 35, 5.7e-8 at 39).
  const io::Hdf5File file(r.out / "fdm" / "snapshots" / "snapshot_000002.h5",
                          io::Hdf5File::Mode::read);
  const auto rho = file.read_dataset("/cells/density").values;
  const auto p = file.read_dataset("/cells/pressure").values;
  ASSERT_EQ(rho.size(), 40U);
  EXPECT_GT(p[18], 1.2e5);  // x = 0.4625: the pulse crossed the face at x = 0.4
  EXPECT_GT(p[24], 1.1e5);
  for (std::size_t i = 35; i < 40; ++i) {
    EXPECT_NEAR(rho[i], 1.2, 1.2e-5) << "cell " << i;
    EXPECT_NEAR(p[i], 1.0e5, 1.0) << "cell " << i;
    EXPECT_LT(std::abs(p[i] - 1.0e5), std::abs(p[i - 1] - 1.0e5)) << "cell " << i;
  }
  // While asleep the audit counts the FDM's cells of the whole (closed) tube.
  EXPECT_LT(std::abs(r.report.mass_error), 1e-14);
  EXPECT_LT(std::abs(r.report.energy_error), 1e-14);
}

TEST(Dormant, The_pulse_wakes_the_zone_once_and_the_audit_is_continuous) {
  testing::StillMpm mpm;
  const auto r = run(tube(1.2e5, true), mpm, "wake");
  const auto& activation = r.summary["details"]["activation"];
  ASSERT_EQ(activation["activated"], true);
  const double t_on = activation["time_s"];
  // The front leaves x = 0.25 at t = 0 and passes the strip (cell centres
  // 0.3875, 0.4125) after ~0.14 m / 342 m/s = 0.4 ms (earlier: the scheme smears it).
  EXPECT_GT(t_on, 1.0e-4);
  EXPECT_LT(t_on, 5.0e-4);
  EXPECT_GT(activation["trigger_pressure_pa"].get<double>(), 1.2e5);
  EXPECT_DOUBLE_EQ(mpm.activated_at.load(), t_on);  // the Activate carried the switch time
  EXPECT_GT(mpm.requests_after_setup.load(), 1);
  // The zone's content changed hands: the stand-in's particles (still air, 24 cells)
  // replace the FDM's zone cells, which hold the part of the pulse that crossed the
  // face before the switch: a little more mass, reported, not counted as audit error.
  const auto& jump = activation["audit_switch"];
  EXPECT_NEAR(jump["particles"]["mass"].get<double>(), 24 * 1.2 * 2.5e-6, 1e-15);
  const double cells = jump["fdm_cells"]["mass"].get<double>();
  EXPECT_GT(cells, 24 * 1.2 * 2.5e-6);
  EXPECT_NEAR(jump["relative_mass_change"].get<double>(),
              (24 * 1.2 * 2.5e-6 - cells) / (40 * 1.2 * 2.5e-6), 1e-12);
  EXPECT_GT(jump["relative_mass_change"].get<double>(), -1e-2);
}

TEST(Dormant, A_threshold_below_the_ambient_pressure_wakes_the_zone_at_the_start) {
  testing::StillMpm mpm;
  const auto r = run(tube(5.0e4, false), mpm, "early");
  EXPECT_EQ(r.summary["details"]["activation"]["activated"], true);
  EXPECT_EQ(r.summary["details"]["activation"]["time_s"], 0.0);
  EXPECT_EQ(mpm.activated_at.load(), 0.0);
  EXPECT_LT(std::abs(r.report.mass_error), 1e-14);
}

}  // namespace
}  // namespace mpfd::coupler
