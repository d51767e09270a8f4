// The CFDMP loop (coupler/run/coupled_run.hpp) driving the real `fdm_solver
// serve` (a thread, or a child process) and a still-air stand-in for the MPM.
#include "coupler/run/coupled_run.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <thread>

#include "common/config/scene_loader.hpp"
#include "common/core/error.hpp"
#include "common/core/require.hpp"
#include "common/io/output_directory.hpp"
#include "cosim/arrays.hpp"
#include "cosim/player.hpp"
#include "cosim/recorder.hpp"
#include "coupler/run/zone_layout.hpp"
#include "fdm_solver/serve/serve.hpp"
#include "tests/unit/coupler/run/still_mpm.hpp"

namespace mpfd::coupler {
namespace {

using ::testing::AllOf;
using ::testing::AnyOf;
using ::testing::HasSubstr;

// Air at rest in a 1 m tube of 40 cells: FDM [0, 0.6], MPM [0.4, 1], w = 5 cells.
std::string quiet_tube(double end) {
  return testing::still_tube_scene("quiet_tube", end);
}

void serve_fdm(zmq::context_t& context, const std::string& endpoint, const std::string& name) {
  fdm::serve(
      context,
      {.endpoint = endpoint, .name = name, .idle_timeout = std::chrono::milliseconds(10000)});
}

testing::StillMpm* g_mpm = nullptr;  // the stand-in a thread serves (ServeFunction has no state)
void serve_mpm(zmq::context_t& context, const std::string& endpoint, const std::string&) {
  testing::serve_still_mpm(context, endpoint, *g_mpm);
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpfd-coupler-test-" + name);
  std::filesystem::remove_all(dir);
  io::prepare_output_directory(dir, false);
  return dir;
}

CoupledRunOptions options(const std::filesystem::path& out) {
  CoupledRunOptions o;
  o.out_dir = out;
  o.progress = false;
  return o;
}

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

struct Harness {
  explicit Harness(double timeout_seconds = 5.0) {
    mpm.cell_volume = 0.025 * 0.01 * 0.01;
    g_mpm = &mpm;
    cosim::TransportOptions transport;
    transport.reply_timeout = std::chrono::milliseconds(std::llround(timeout_seconds * 1e3));
    hub = std::make_unique<cosim::Hub>(context, "inproc://coupler-run-test", transport);
  }
  /// The FDM and the stand-in MPM, each serving in a thread of this process.
  std::vector<std::unique_ptr<SolverHandle>> start_solvers() {
    std::vector<std::unique_ptr<SolverHandle>> solvers;
    solvers.push_back(start_thread("fdm", serve_fdm, context, hub->endpoint()));
    solvers.push_back(start_thread("mpm", serve_mpm, context, hub->endpoint()));
    return solvers;
  }
  zmq::context_t context;
  testing::StillMpm mpm;
  std::unique_ptr<cosim::Hub> hub;
};

TEST(CoupledRun, Quiet_air_stays_quiet_and_conserves_over_the_zones) {
  Harness h;
  const std::string text = quiet_tube(2.0e-3);
  const auto scene = config::parse_scene(text, "quiet.yaml");
  auto solvers = h.start_solvers();
  const auto out = fresh_dir("quiet");
  const auto report = run_cfdmp(scene, text, *h.hub, solvers, options(out));

  // The FDM proposes 73.2 us for c = 341.6 m/s, dx = 25 mm (its CFL 0.5 counts
  // half steps), the MPM stand-in 1 s; the strip cells' cap, the MPM's CFL 0.5 on
  // the same air, 36.6 us: 2 ms / 36.6 us = 54.6 -> 55 steps, the output at 1 ms
  // cutting one.
  EXPECT_GE(report.steps, 55);
  EXPECT_LE(report.steps, 56);
  EXPECT_DOUBLE_EQ(report.time, 2.0e-3);
  EXPECT_LT(std::abs(report.mass_error), 1e-14);
  EXPECT_LT(std::abs(report.energy_error), 1e-14);
  EXPECT_EQ(h.mpm.injected_mass.load(), 0.0);
  const auto summary = read_json(out / "summary.json");
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_EQ(summary["details"]["steps_limited_by"]["fdm"].get<int>(), 0);
  EXPECT_GE(summary["details"]["steps_limited_by"]["strip"].get<int>(), 55);
  // FDM owned: 16 cells x 1.2 kg/m^3 x 2.5e-6 m^3; MPM: 24 cells.
  EXPECT_NEAR(summary["details"]["zones"]["fdm_owned"]["mass"].get<double>(), 16 * 1.2 * 2.5e-6,
              1e-15);
  EXPECT_NEAR(summary["details"]["zones"]["mpm"]["mass"].get<double>(), 24 * 1.2 * 2.5e-6, 1e-15);
  EXPECT_TRUE(std::filesystem::exists(out / "fdm"));
}

/// The peer of each step's first Exchange request, in the order the coupler sent them.
std::vector<std::string> first_request_of_each_step(const std::filesystem::path& recording) {
  std::vector<std::string> first;
  std::uint64_t step = 0;
  cosim::Player player(recording);
  while (auto record = player.next()) {
    const auto& header = record->message.header;
    if (record->direction != cosim::v1::DIRECTION_SENT || !header.has_exchange()) continue;
    if (header.envelope().step() == step && !first.empty()) continue;
    step = header.envelope().step();
    first.push_back(record->peer);
  }
  return first;
}

/// Runs scene `text` with the harness's solvers to its end, recording every message
/// into the fresh folder `name`; returns the recording.
std::filesystem::path recorded_run(Harness& h, const std::string& text, const std::string& name) {
  const auto scene = config::parse_scene(text, name + ".yaml");
  auto solvers = h.start_solvers();
  const auto out = fresh_dir(name);
  const auto recording = out / "run.mpfdrec";
  cosim::Recorder recorder(recording);
  h.hub->attach_recorder(&recorder);
  (void)run_cfdmp(scene, text, *h.hub, solvers, options(out));
  h.hub->attach_recorder(nullptr);
  recorder.close();
  return recording;
}

std::vector<std::string> first_requests_with_mpm_advance_of(double wall_seconds) {
  Harness h;
  h.mpm.advance_wall_seconds = wall_seconds;
  return first_request_of_each_step(recorded_run(h, quiet_tube(4.0e-4), "send-order"));
}

TEST(CoupledRun, The_solver_slower_in_the_last_advance_gets_its_request_first) {
  // Over ipc/tcp the solver woken second can wait a few ms for a core behind the
  // first: the critical one goes first. Steps 0 and 1 follow no advance: FDM first.
  const auto slow_mpm = first_requests_with_mpm_advance_of(1.0);
  ASSERT_GE(slow_mpm.size(), 6U);
  EXPECT_EQ(slow_mpm[0], "fdm");
  EXPECT_EQ(slow_mpm[1], "fdm");
  for (std::size_t n = 2; n < slow_mpm.size(); ++n) EXPECT_EQ(slow_mpm[n], "mpm") << "step " << n;
  // The stand-in's 0 s against a real FDM advance: the FDM first throughout.
  for (const auto& peer : first_requests_with_mpm_advance_of(0.0)) EXPECT_EQ(peer, "fdm");
}

TEST(CoupledRun, A_silent_solver_is_named_within_the_timeout_and_the_other_is_shut_down) {
  Harness h(0.5);
  h.mpm.silent_from_step = 5;
  const std::string text = quiet_tube(2.0e-3);
  const auto scene = config::parse_scene(text, "quiet.yaml");
  auto solvers = h.start_solvers();
  const auto out = fresh_dir("silent");
  const auto start = std::chrono::steady_clock::now();
  try {
    run_cfdmp(scene, text, *h.hub, solvers, options(out));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), AllOf(HasSubstr("'mpm'"), HasSubstr("0.5 s")));
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  // The FDM got Shutdown and ended by itself.
  EXPECT_THAT(solvers[0]->ended().value_or("running"), HasSubstr("returned"));
  const auto summary = read_json(out / "summary.json");
  EXPECT_EQ(summary["status"], "failed");
  EXPECT_THAT(summary["error"].get<std::string>(), HasSubstr("'mpm'"));
}

// A solver that answers with a fatal Error stops (proto §9): the run must stop at
// once with its message, not send it a Shutdown and wait a reply timeout for the
// answer (5 s: docs/stability.md, a cfdmp run whose FDM failed at step 0). The
// stand-in lingers connected for 1 s after its error, as a process tearing down.
TEST(CoupledRun, A_solvers_fatal_error_at_step_0_stops_the_run_at_once_with_its_message) {
  Harness h(5.0);
  h.mpm.fatal_at_step = 0;
  h.mpm.linger_ms = 1000;
  const std::string text = quiet_tube(2.0e-3);
  const auto scene = config::parse_scene(text, "quiet.yaml");
  auto solvers = h.start_solvers();
  const auto out = fresh_dir("fatal");
  const auto start = std::chrono::steady_clock::now();
  try {
    run_cfdmp(scene, text, *h.hub, solvers, options(out));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), AllOf(HasSubstr("solver 'mpm' reported ERROR_CODE_NUMERICAL"),
                                    HasSubstr("unphysical state of particle 0")));
  }
  // A correctness bound (well under the 5 s reply timeout), not a speed benchmark.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
  EXPECT_THAT(solvers[0]->ended().value_or("running"), HasSubstr("returned"));
  EXPECT_EQ(read_json(out / "summary.json")["status"], "failed");
}

// The real FDM failing in its first step (water at ambient pressure beside air in
// its grid: tension at the contact, docs/stability.md): the run stops with the
// FDM's own message, within a fraction of the 5 s reply timeout.
TEST(CoupledRun, An_fdm_failing_at_step_0_stops_the_run_with_its_message) {
  Harness h(5.0);
  std::string text = quiet_tube(2.0e-3);
  text.replace(text.find("initial:"), 0,
               "  water: {eos: {type: polynomial, rho0: 1000, A1: 2.2e9, A2: 9.54e9, A3: 1.457e10, "
               "B0: 0.28, B1: 0.28, T1: 2.2e9}}\n"
               "bodies:\n  - {name: water, material: water, density: 1000, pressure: 1.0e5, "
               "shape: {box: {lower: [0.1, 0, 0], upper: [0.2, 0.01, 0.01]}}}\n");
  const auto scene = config::parse_scene(text, "water.yaml");
  auto solvers = h.start_solvers();
  const auto out = fresh_dir("fdm-step-0");
  const auto start = std::chrono::steady_clock::now();
  try {
    run_cfdmp(scene, text, *h.hub, solvers, options(out));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(),
                AllOf(HasSubstr("solver 'fdm' reported ERROR_CODE_NUMERICAL"),
                      HasSubstr("fdm_solver: unphysical state in cell"), HasSubstr("(step 0)")));
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
  EXPECT_TRUE(h.mpm.shut_down);  // the other solver got Shutdown
}

// An MPM zone with no mass next to the face (T (4-1) gives the ghost cells nothing):
// the error names the time, the step, the cell and its position, the cause and the act.
TEST(CoupledRun, An_emptied_mpm_zone_is_named_with_time_step_cell_position_and_what_to_do) {
  Harness h;
  h.mpm.density = 0;
  const std::string text = quiet_tube(2.0e-3);
  const auto scene = config::parse_scene(text, "quiet.yaml");
  const auto ghost = make_zone_layout(scene).ghost_cells;
  auto solvers = h.start_solvers();
  const auto out = fresh_dir("empty");
  try {
    run_cfdmp(scene, text, *h.hub, solvers, options(out));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    const std::string cell = "(" + std::to_string(ghost.lo[0]) + ", 0, 0)";
    const std::string x = number_text((static_cast<double>(ghost.lo[0]) + 0.5) * 0.025, 6);
    EXPECT_THAT(error.what(),
                AllOf(HasSubstr("at t = 0 s (step 1)"), HasSubstr("ghost cell " + cell),
                      HasSubstr("at (" + x + ", 0.005, 0.005) m"), HasSubstr("no MPM nodal mass"),
                      HasSubstr("MPM zone has emptied"), HasSubstr("wall or symmetry"),
                      HasSubstr("move the zone face")))
        << "ghost cells " << box_text(ghost);
  }
}

// Gas drawn out of the MPM zone by a low pressure on the FDM's side, and an MPM
// whose particles never cross the face (the stand-in stays at rest): the FDM's
// flux out of the zone is taken back from cell k-w every step and nothing comes
// in, so that cell empties. The error says so, and that time.cfl does not help.
TEST(CoupledRun, A_face_cell_the_deposits_empty_is_named_as_the_cause_of_the_fdm_failure) {
  Harness h;
  std::string text = quiet_tube(2.0e-3);
  text +=
      "bodies:\n  - {name: low, material: air, density: 0.12, pressure: 1.0e4,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [0.3, 0.01, 0.01]}}}\n";
  const auto scene = config::parse_scene(text, "drawn_out.yaml");
  const auto face = make_zone_layout(scene).strip_cells.lo[0];  // cell k-w
  auto solvers = h.start_solvers();
  const auto out = fresh_dir("drawn-out");
  try {
    run_cfdmp(scene, text, *h.hub, solvers, options(out));
    FAIL() << "expected an error";
  } catch (const Error& error) {
    const std::string cell = "(" + std::to_string(face) + ", 0, 0)";
    EXPECT_THAT(error.what(),
                AllOf(HasSubstr("beside the coupling face"), HasSubstr("FDM cell " + cell),
                      HasSubstr("the particles that crossed brought 0 kg"),
                      HasSubstr("a smaller time.cfl or a finer grid does not cure this")));
  }
  const auto summary = read_json(out / "summary.json");
  EXPECT_GE(summary["details"]["crossing"]["max_face_cell_drain"].get<double>(), 0.5);
}

/// The x internal force [N] of the interface nodes in the last Exchange the coupler
/// sent the MPM (recorded), or NaN if none carried them.
double last_interface_force(const std::filesystem::path& recording) {
  double force = std::numeric_limits<double>::quiet_NaN();
  cosim::Player player(recording);
  while (auto record = player.next()) {
    const auto& m = record->message;
    if (record->direction != cosim::v1::DIRECTION_SENT || record->peer != "mpm") continue;
    for (const auto& a : m.header.arrays())
      if (a.group() == "interface_nodes" && a.name() == "internal_force")
        force = cosim::view_array<double>(m, "interface_nodes", "internal_force").values()[0];
  }
  return force;
}

// (4-9)'s push with the MPM's face-cell mass counts a solid there by its own volume
// (docs/coupler.md, Deviations): two steel particles of 0.3 V_c each in cell k-w+1 make
// the air at rest push with 0.6 V_c, p 0.6 V_c / h = 1e5 * 1.5e-6 / 0.025 = 6 N on the
// face node; not with their mass at the air's density (7890 / 1.2 V_c: 65 750 N, random
// seed 17), nor with V_c as if the cell were empty (10 N).
TEST(CoupledRun, A_solid_in_the_face_cell_is_pushed_by_the_fdm_with_its_own_volume) {
  Harness h;
  h.mpm.face_material = 1;  // steel, the scene's second material
  h.mpm.face_density = 7890;
  h.mpm.face_volume = 0.3 * h.mpm.cell_volume;
  std::string text = quiet_tube(4.0e-4);
  const std::string air = "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n";
  text.replace(text.find(air), air.size(),
               air +
                   "  steel:\n"
                   "    eos: {type: mie_gruneisen, rho0: 7890, C0: 4569, S: 1.49, gamma0: 2.17}\n"
                   "    strength: {type: elastic, shear_modulus: 8.18e10}\n");
  text +=
      "bodies:\n  - {name: plate, material: steel, density: 7890, pressure: 1.0e5,\n"
      "     shape: {box: {lower: [0.9, 0, 0], upper: [0.95, 0.01, 0.01]}}}\n";
  ASSERT_EQ(config::parse_scene(text, "plate.yaml").materials[1].name, "steel");
  const auto recording = recorded_run(h, text, "solid-push");
  EXPECT_NEAR(std::abs(last_interface_force(recording)), 6.0, 1e-9);
}

// The killed solver is named at once (the hub watches the solvers while it waits),
// not after the 5 s reply timeout.
TEST(CoupledRun, A_killed_solver_process_is_named_at_once_and_outputs_are_kept) {
  Harness h(5.0);
  const std::string ipc =
      "ipc://" + (std::filesystem::temp_directory_path() / "mpfd-coupler-kill-test").string();
  const std::string fdm_endpoint = h.hub->bind_also(ipc);
  const std::string text = quiet_tube(10.0);  // ~270000 steps: runs until killed
  const auto scene = config::parse_scene(text, "quiet.yaml");
  const auto out = fresh_dir("kill");
  std::vector<std::unique_ptr<SolverHandle>> solvers;
  solvers.push_back(start_process("fdm", {MPFD_FDM_SOLVER, "serve", "--endpoint", fdm_endpoint},
                                  (out / "fdm_solver.log").string()));
  solvers.push_back(start_thread("mpm", serve_mpm, h.context, h.hub->endpoint()));
  std::atomic<std::chrono::steady_clock::time_point> killed_at{};
  std::thread killer([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    killed_at = std::chrono::steady_clock::now();
    ::kill(*solvers[0]->process_id(), SIGKILL);
  });
  try {
    run_cfdmp(scene, text, *h.hub, solvers, options(out));
    ADD_FAILURE() << "expected an error";
  } catch (const Error& error) {
    // Killed while the coupler waits for its reply, or between the reply and the next
    // send: either way the solver and its signal are named.
    EXPECT_THAT(error.what(), AllOf(AnyOf(HasSubstr("solver 'fdm' ended while the coupler waited"),
                                          HasSubstr("cannot send to solver 'fdm'")),
                                    HasSubstr("killed by signal 9")));
  }
  killer.join();
  // A correctness bound (well under the 5 s reply timeout), not a speed benchmark.
  EXPECT_LT(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - killed_at.load()).count(),
      3.0);
  EXPECT_FALSE(std::filesystem::is_empty(out / "fdm"));  // the t = 0 output is kept
  EXPECT_EQ(read_json(out / "summary.json")["status"], "failed");
}

}  // namespace
}  // namespace mpfd::coupler
