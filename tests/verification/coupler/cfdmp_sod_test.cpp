// V1 (Sod's tube) by CFDMP across the FDM/MPM zone boundary
// (configs/cfdmp_sod_1d.yaml: FDM [0, 0.65], MPM [0.6, 1], w = 5 cells, CFL 0.1)
// against the exact Riemann solution, next to pure FDM and pure MPM runs of the
// same scene. All three are read back from their snapshots at t = 0.2 s the
// same way. Errors: FDM part = mean |rho - exact| over the FDM cells left of
// the face (x < 0.6); MPM part = volume-weighted mean |rho_p - exact(x_p)| over
// the particles right of it; reflection = max |p - p*| / p* over the cells in
// [0.52, 0.58] (the star region next to the face: a wave reflected by the zone
// boundary would show there). Closed box (walls): the coupled audit's mass and
// energy over t = 0.52 s (> 1000 steps).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "common/config/scene_loader.hpp"
#include "common/io/hdf5_file.hpp"
#include "common/io/output_directory.hpp"
#include "coupler/run/coupled_run.hpp"
#include "coupler/run/launch.hpp"
#include "fdm_solver/serve/serve.hpp"
#include "fdm_solver/standalone_run.hpp"
#include "mpm_solver/standalone_run.hpp"
#include "tests/verification/support/exact_riemann.hpp"

namespace mpfd::coupler {
namespace {

constexpr double kFace = 0.6;
constexpr double kEnd = 0.2;

const std::string kScene = std::string(MPFD_SOURCE_DIR) + "/configs/cfdmp_sod_1d.yaml";

std::filesystem::path temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("mpfd-cfdmp-sod-" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

const verification::ExactRiemann& exact() {
  static const verification::ExactRiemann solution({1.0, 0.0, 1.0}, {0.125, 0.0, 0.1}, 1.4);
  return solution;
}

struct Profile {
  std::vector<double> x, density, pressure, volume;
};

/// The FDM cells (x < limit) of `dir`'s snapshot `index`.
Profile fdm_cells(const std::filesystem::path& dir, int index, double limit) {
  char name[32];
  std::snprintf(name, sizeof name, "snapshot_%06d.h5", index);
  const io::Hdf5File file(dir / "snapshots" / name, io::Hdf5File::Mode::read);
  const auto rho = file.read_dataset("/cells/density").values;
  const auto p = file.read_dataset("/cells/pressure").values;
  Profile out;
  const double dx = 1.0 / static_cast<double>(rho.size());
  for (std::size_t i = 0; i < rho.size(); ++i) {
    const double x = (static_cast<double>(i) + 0.5) * dx;
    if (x >= limit) continue;
    out.x.push_back(x);
    out.density.push_back(rho[i]);
    out.pressure.push_back(p[i]);
    out.volume.push_back(dx);
  }
  return out;
}

/// The MPM particles (x >= limit) of `dir`'s snapshot `index`.
Profile mpm_particles(const std::filesystem::path& dir, int index, double limit) {
  char name[32];
  std::snprintf(name, sizeof name, "snapshot_%06d.h5", index);
  const io::Hdf5File file(dir / "snapshots" / name, io::Hdf5File::Mode::read);
  const auto position = file.read_dataset("/particles/position").values;
  const auto rho = file.read_dataset("/particles/density").values;
  const auto p = file.read_dataset("/particles/pressure").values;
  const auto m = file.read_dataset("/particles/mass").values;
  Profile out;
  for (std::size_t i = 0; i < rho.size(); ++i) {
    if (position[3 * i] < limit) continue;
    out.x.push_back(position[3 * i]);
    out.density.push_back(rho[i]);
    out.pressure.push_back(p[i]);
    out.volume.push_back(m[i] / rho[i]);
  }
  return out;
}

double mean_density_error(const Profile& f) {
  double sum = 0, volume = 0;
  for (std::size_t i = 0; i < f.x.size(); ++i) {
    sum += std::abs(f.density[i] - exact().sample((f.x[i] - 0.5) / kEnd).density) * f.volume[i];
    volume += f.volume[i];
  }
  return sum / volume;
}

double star_pressure_deviation(const Profile& f) {
  double worst = 0;
  const double p_star = exact().star_pressure();
  for (std::size_t i = 0; i < f.x.size(); ++i)
    if (f.x[i] > 0.52 && f.x[i] < 0.58)
      worst = std::max(worst, std::abs(f.pressure[i] - p_star) / p_star);
  return worst;
}

/// x, density and pressure of each profile and of the exact solution, for
/// cfdmp_sod_figure.sh (docs/figures/cfdmp_sod.svg).
void write_profiles(const std::filesystem::path& file,
                    const std::vector<std::pair<std::string, Profile>>& profiles) {
  std::ofstream out(file);
  out << "series,x,density,pressure\n";
  for (const auto& [name, f] : profiles)
    for (std::size_t i = 0; i < f.x.size(); ++i)
      out << name << ',' << f.x[i] << ',' << f.density[i] << ',' << f.pressure[i] << '\n';
  for (int i = 0; i <= 1000; ++i) {
    const double x = i / 1000.0;
    const auto e = exact().sample((x - 0.5) / kEnd);
    out << "exact," << x << ',' << e.density << ',' << e.pressure << '\n';
  }
}

nlohmann::json run_coupled(const std::filesystem::path& scene_file,
                           const std::filesystem::path& out) {
  LaunchOptions launch;  // embedded
  CoupledRunOptions options;
  options.out_dir = out;
  options.progress = false;
  launch_run(scene_file, launch, options, "");
  std::ifstream in(out / "summary.json");
  return nlohmann::json::parse(in);
}

TEST(CfdmpSod, Fast_accuracy_against_exact_and_pure_solvers) {
  const auto coupled = temp_dir("coupled");
  run_coupled(kScene, coupled);

  auto scene = config::load_scene(kScene);
  scene.zones.reset();
  scene.solver.method = config::Method::fdm;
  const auto pure_fdm = temp_dir("fdm");
  fdm::run_standalone(scene, {.scene_file = kScene, .out_dir = pure_fdm});
  scene.solver.method = config::Method::mpm;
  const auto pure_mpm = temp_dir("mpm");
  mpm::run_standalone(scene, {.scene_file = kScene, .out_dir = pure_mpm});

  const int last = 10;  // t = 0.2 s at output interval 0.02 s
  write_profiles(std::filesystem::temp_directory_path() / "mpfd-cfdmp-sod-profiles.csv",
                 {{"cfdmp_fdm", fdm_cells(coupled / "fdm", last, kFace)},
                  {"cfdmp_mpm", mpm_particles(coupled / "mpm", last, kFace)},
                  {"pure_fdm", fdm_cells(pure_fdm, last, 2.0)},
                  {"pure_mpm", mpm_particles(pure_mpm, last, 0.0)}});
  const double fdm_coupled = mean_density_error(fdm_cells(coupled / "fdm", last, kFace));
  const double fdm_pure = mean_density_error(fdm_cells(pure_fdm, last, kFace));
  const double mpm_coupled = mean_density_error(mpm_particles(coupled / "mpm", last, kFace));
  const double mpm_pure = mean_density_error(mpm_particles(pure_mpm, last, kFace));
  const double reflect_coupled = star_pressure_deviation(fdm_cells(coupled / "fdm", last, kFace));
  const double reflect_pure = star_pressure_deviation(fdm_cells(pure_fdm, last, kFace));
  std::printf("FDM part mean |rho err|: coupled %.4e, pure FDM %.4e\n", fdm_coupled, fdm_pure);
  std::printf("MPM part mean |rho err|: coupled %.4e, pure MPM %.4e\n", mpm_coupled, mpm_pure);
  std::printf("star-region max |p - p*|/p* near the face: coupled %.4e, pure FDM %.4e\n",
              reflect_coupled, reflect_pure);
  // Measured (docs/coupler.md): FDM part 8.81e-3 vs 8.75e-3 pure; MPM part
  // 1.54e-2 vs 2.52e-2 pure (part of it is fed by the FDM); star-region
  // deviation 1.28e-2 vs 1.26e-2 pure (no visible reflection from the face).
  EXPECT_LT(fdm_coupled, 1.05 * fdm_pure);
  EXPECT_LT(mpm_coupled, 1.0 * mpm_pure);
  EXPECT_LT(reflect_coupled, 1.1 * reflect_pure);
}

TEST(CfdmpSod, Fast_closed_box_conservation_over_1000_steps) {
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  yaml.replace(yaml.find("end: 0.2,"), 9, "end: 0.52,");
  const auto scene_file = temp_dir("long-scene.yaml");
  std::ofstream(scene_file) << yaml;
  const auto summary = run_coupled(scene_file, temp_dir("long"));
  const double mass = summary["conservation"]["mass"]["relative_error"];
  const double energy = summary["conservation"]["energy"]["relative_error"];
  const double momentum = summary["conservation"]["momentum_x"]["relative_error"];
  const auto steps = summary["steps"].get<std::int64_t>();
  std::printf("closed box, %lld steps: mass error %.4e, energy error %.4e, momentum_x %.4e\n",
              static_cast<long long>(steps), mass, energy, momentum);
  EXPECT_GE(steps, 1000);
  EXPECT_TRUE(summary["details"]["protocol"]["fdm_face_crossing"].get<bool>());
  // Protocol v1.1: the parcels take the mass the FDM put through the face, so
  // mass is conserved to round-off (measured -2.4e-16 over 1108 steps; v1.0,
  // with T (4-13): -1.17e-3). Energy is not: the MPM side receives the face
  // pressure through the interface force (4-9) (measured -2.2e-4 with T's V_c in (4-9);
  // -1.41e-3 since the FDM pushes with the MPM's face-cell mass over its density, which
  // lags the FDM's behind the shock while the parcels wait: docs/coupler.md; v1.0 -2.2e-3).
  EXPECT_LT(std::abs(mass), 1e-12);
  EXPECT_LT(std::abs(energy), 1.6e-3);
  // Momentum starts at 0, so its entry is absolute (kg m/s): the two walls'
  // impulses enter through both solvers' boundary_outflow (v1.1) and must cancel
  // the change of the zones' momentum. Measured: drift 3.4e-8 against a net wall
  // impulse of 2.76e-5 (1.2e-3 of it; without the outflow terms the drift would be the impulse).
  const double impulse = summary["conservation"]["momentum_x"]["boundary_outflow"];
  EXPECT_GT(std::abs(impulse), 1e-5);
  EXPECT_LT(std::abs(momentum), 5e-3 * std::abs(impulse));
}

TEST(CfdmpSod, Fast_closed_box_with_a_gimp_mpm_feeds_the_node_layer_outside_the_face) {
  // The same closed box with uGIMP particles (half-width h/4): those within h/4 of
  // the face, injected ones nearly always, reach the node layer outside it. The
  // coupler feeds that layer from the FDM cells k-w and k-w-1 (outer_node_terms);
  // without them it held the particles' slivers of mass only and they expanded as
  // into a vacuum. Measured energy error: -4.17e-3 without the outer nodes (3 x the
  // linear MPM's -1.41e-3), -4.46e-4 with them; mass round-off either way.
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  yaml.replace(yaml.find("end: 0.2,"), 9, "end: 0.52,");
  yaml.replace(yaml.find("shape_function: linear"), 22, "shape_function: gimp");
  const auto scene_file = temp_dir("gimp-scene.yaml");
  std::ofstream(scene_file) << yaml;
  const auto summary = run_coupled(scene_file, temp_dir("gimp"));
  const double mass = summary["conservation"]["mass"]["relative_error"];
  const double energy = summary["conservation"]["energy"]["relative_error"];
  std::printf("closed box, uGIMP MPM: mass error %.4e, energy error %.4e\n", mass, energy);
  EXPECT_LT(std::abs(mass), 1e-12);
  EXPECT_LT(std::abs(energy), 1.0e-3);
}

void serve_fdm_v1_0(zmq::context_t& context, const std::string& endpoint, const std::string&) {
  fdm::serve(context, {.endpoint = endpoint, .offer_v1_0_only = true});
}

TEST(CfdmpSod, Fast_closed_box_with_a_v1_0_fdm_falls_back_to_T_4_13) {
  // An FDM that does not offer face_crossing: the parcels come from T (4-10)
  // ... (4-14) again, and mass is off by their difference from the FDM's flux.
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  yaml.replace(yaml.find("end: 0.2,"), 9, "end: 0.52,");
  const auto scene = config::parse_scene(yaml, "closed.yaml");
  zmq::context_t context;
  cosim::Hub hub(context, "inproc://cfdmp-v1-0");
  std::vector<std::unique_ptr<SolverHandle>> solvers;
  solvers.push_back(start_thread("fdm", serve_fdm_v1_0, context, hub.endpoint()));
  solvers.push_back(start_thread("mpm", embedded_serve("mpm"), context, hub.endpoint()));
  const auto out = temp_dir("v1-0");
  io::prepare_output_directory(out, true);
  CoupledRunOptions options;
  options.out_dir = out;
  options.progress = false;
  const auto report = run_cfdmp(scene, yaml, hub, solvers, options);
  std::ifstream summary_file(out / "summary.json");
  const auto summary = nlohmann::json::parse(summary_file);
  std::printf("closed box, v1.0 FDM, %lld steps: mass error %.4e, energy error %.4e\n",
              static_cast<long long>(report.steps), report.mass_error, report.energy_error);
  EXPECT_FALSE(summary["details"]["protocol"]["fdm_face_crossing"].get<bool>());
  EXPECT_FALSE(summary["details"]["protocol"]["fdm_outflow"].get<bool>());
  EXPECT_GT(std::abs(report.mass_error), 1e-4);  // measured -1.1e-3
  EXPECT_LT(std::abs(report.mass_error), 2e-3);
}

TEST(CfdmpSod, Fast_open_ends_audit_counts_the_outflow) {
  // Both x faces outflow, to t = 0.52 s: the shock leaves through the MPM's
  // face (x = 1, t ~ 0.29 s), the rarefaction reaches the FDM's (x = 0, t ~ 0.42 s).
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  yaml.replace(yaml.find("end: 0.2,"), 9, "end: 0.52,");
  yaml.replace(yaml.find("x_lower: wall, x_upper: wall"), 28, "x_lower: outflow, x_upper: outflow");
  const auto scene_file = temp_dir("open-scene.yaml");
  std::ofstream(scene_file) << yaml;
  const auto summary = run_coupled(scene_file, temp_dir("open"));
  const auto& zones = summary["details"]["zones"];
  const double fdm_out = zones["fdm_outflow"]["mass"], mpm_out = zones["mpm_outflow"]["mass"];
  const double mass = summary["conservation"]["mass"]["relative_error"];
  const double energy = summary["conservation"]["energy"]["relative_error"];
  const double initial = summary["conservation"]["mass"]["initial"];
  std::printf(
      "open ends: outflow fdm %.4e kg, mpm %.4e kg (of %.4e); mass error %.4e, energy "
      "error %.4e\n",
      fdm_out, mpm_out, initial, mass, energy);
  EXPECT_TRUE(summary["details"]["protocol"]["fdm_outflow"].get<bool>());
  EXPECT_TRUE(summary["details"]["protocol"]["mpm_outflow"].get<bool>());
  // Gas enters at x = 0 (the rarefaction draws it in: fdm_out < 0) and leaves at
  // x = 1, each over 1 % of the mass: an audit without them would miss that.
  EXPECT_GT(std::abs(fdm_out), 1e-2 * initial);
  EXPECT_GT(mpm_out, 1e-2 * initial);
  EXPECT_DOUBLE_EQ(summary["conservation"]["mass"]["boundary_outflow"].get<double>(),
                   fdm_out + mpm_out);
  EXPECT_LT(std::abs(mass), 1e-12);
  EXPECT_LT(std::abs(energy), 5e-3);
}

/// configs/cfdmp_sod_1d.yaml with zones.mpm.activation_pressure = `threshold` (Pa, read as SI).
std::filesystem::path dormant_scene(const std::string& name, double threshold) {
  std::ifstream in(kScene);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string mpm_zone = "upper: [1, 0.01, 0.01]}";
  const auto at = yaml.find(mpm_zone, yaml.find("mpm: {lower: [0.6"));
  yaml.replace(at, mpm_zone.size(),
               "upper: [1, 0.01, 0.01], activation_pressure: " + std::to_string(threshold) + "}");
  const auto file = temp_dir(name + ".yaml");
  std::ofstream(file) << yaml;
  return file;
}

/// The cells of snapshot `index` of `dir`, all of them.
std::vector<double> all_cells(const std::filesystem::path& dir, int index, const char* field) {
  char name[32];
  std::snprintf(name, sizeof name, "snapshot_%06d.h5", index);
  const io::Hdf5File file(dir / "snapshots" / name, io::Hdf5File::Mode::read);
  return file.read_dataset(std::string("/cells/") + field).values;
}

// (a) The zone never wakes (max pressure 1 Pa < 10 Pa): the FDM ran alone over the
// whole grid, so its snapshots are the pure FDM run's but for the step sizes before
// each output (the standalone loop halves the last two steps, the coupler cuts the
// last one: measured 6.4e-5 max relative difference), and the MPM wrote nothing.
TEST(CfdmpSod, Fast_a_zone_that_never_wakes_leaves_a_pure_fdm_run) {
  const auto scene_file = dormant_scene("never", 10.0);
  const auto coupled = temp_dir("never");
  const auto summary = run_coupled(scene_file, coupled);
  EXPECT_EQ(summary["details"]["activation"]["activated"], false);
  EXPECT_TRUE(summary["details"]["activation"]["time_s"].is_null());
  EXPECT_FALSE(std::filesystem::exists(coupled / "mpm" / "snapshots"));

  auto scene = config::load_scene(kScene);
  scene.zones.reset();
  scene.solver.method = config::Method::fdm;
  const auto pure = temp_dir("never-fdm");
  fdm::run_standalone(scene, {.scene_file = kScene, .out_dir = pure});
  double worst = 0;
  for (const char* field : {"density", "pressure"}) {
    const auto a = all_cells(coupled / "fdm", 10, field);
    const auto b = all_cells(pure, 10, field);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      worst = std::max(worst, std::abs(a[i] - b[i]) / std::abs(b[i]));
  }
  std::printf("never woken: max relative difference to pure FDM at t = 0.2 s: %.3e\n", worst);
  EXPECT_LT(worst, 5e-4);
  // The audit of a sleeping zone counts the FDM's cells of the whole closed box.
  const double mass = summary["conservation"]["mass"]["relative_error"];
  std::printf("never woken: audit mass error %.3e\n", mass);
  EXPECT_LT(std::abs(mass), 1e-14);
}

// (b) The shock wakes the zone (threshold 0.2 Pa, between p = 0.1 ahead of the shock
// and p* = 0.303 behind it): the switch comes within one step of the time the FDM's
// pressure at the outer strip cell (centre x = 0.595) passes the threshold, read from
// a gauge of a pure FDM run; the errors at t = 0.2 s stay close to the always-on run.
TEST(CfdmpSod, Fast_b_the_shock_wakes_the_zone_and_the_errors_stay_close) {
  constexpr double kThreshold = 0.2;
  const auto dormant = temp_dir("woken");
  const auto summary = run_coupled(dormant_scene("woken", kThreshold), dormant);
  const auto& activation = summary["details"]["activation"];
  ASSERT_EQ(activation["activated"], true);
  const double t_on = activation["time_s"];

  auto scene = config::load_scene(kScene);
  scene.zones.reset();
  scene.solver.method = config::Method::fdm;
  scene.gauges.push_back({"face", {0.595, 0.005, 0.005}});
  const auto pure = temp_dir("woken-fdm");
  fdm::run_standalone(scene, {.scene_file = kScene, .out_dir = pure});
  std::ifstream gauges(pure / "gauges.csv");
  std::string line;
  std::getline(gauges, line);
  std::size_t column = 0;  // of face.pressure in docs/output.md's gauges.csv
  for (std::stringstream names(line);
       std::getline(names, line, ',') && line.rfind("face.pressure", 0) == std::string::npos;)
    ++column;
  double t_fdm = -1, t_before = 0, dt = 0;
  while (std::getline(gauges, line) && t_fdm < 0) {
    std::vector<double> row;
    std::stringstream fields(line);
    for (std::string v; std::getline(fields, v, ',');) row.push_back(std::stod(v));
    if (row.at(column) > kThreshold) {
      t_fdm = row[0];
      dt = row[0] - t_before;
    }
    t_before = row[0];
  }
  ASSERT_GT(t_fdm, 0);
  double t_exact = 0.05;  // the exact shock passes x = 0.595
  while (exact().sample((0.595 - 0.5) / t_exact).pressure < kThreshold) t_exact += 1e-6;
  std::printf(
      "woken at t = %.5f s; FDM gauge at the face passes %.1f Pa at %.5f s (step %.2e s); "
      "exact shock there at %.5f s\n",
      t_on, kThreshold, t_fdm, dt, t_exact);
  EXPECT_LE(std::abs(t_on - t_fdm), 1.01 * dt);

  const auto always = temp_dir("always");
  run_coupled(kScene, always);
  const int last = 10;
  const double fdm_dormant = mean_density_error(fdm_cells(dormant / "fdm", last, kFace));
  const double fdm_always = mean_density_error(fdm_cells(always / "fdm", last, kFace));
  // The MPM's snapshots start at its first output after the switch; each holds
  // the coupled time: the outputs 0.06, 0.08, ..., 0.2 s.
  int mpm_last = -1;
  for (int i = 0;; ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "snapshot_%06d.h5", i);
    if (!std::filesystem::exists(dormant / "mpm" / "snapshots" / name)) break;
    const io::Hdf5File file(dormant / "mpm" / "snapshots" / name, io::Hdf5File::Mode::read);
    const double t = file.read_attribute("/", "time");
    EXPECT_GT(t, t_on);
    EXPECT_NEAR(t, 0.02 * std::ceil(t_on / 0.02 - 1e-9) + 0.02 * i, 1e-12) << name;
    mpm_last = i;
  }
  ASSERT_GE(mpm_last, 0);
  const double mpm_dormant = mean_density_error(mpm_particles(dormant / "mpm", mpm_last, kFace));
  const double mpm_always = mean_density_error(mpm_particles(always / "mpm", last, kFace));
  std::printf("FDM part mean |rho err|: woken %.4e, always on %.4e\n", fdm_dormant, fdm_always);
  std::printf("MPM part mean |rho err|: woken %.4e, always on %.4e\n", mpm_dormant, mpm_always);
  std::printf(
      "woken: audit mass error %.3e, energy error %.3e; the switch replaced the "
      "FDM's zone cells by particles with %.3e of the mass, %.3e of the energy\n",
      summary["conservation"]["mass"]["relative_error"].get<double>(),
      summary["conservation"]["energy"]["relative_error"].get<double>(),
      activation["audit_switch"]["relative_mass_change"].get<double>(),
      activation["audit_switch"]["relative_energy_change"].get<double>());
  EXPECT_LT(fdm_dormant, 1.05 * fdm_always);
  EXPECT_LT(mpm_dormant, 1.1 * mpm_always);
}

// A 2D blast box with a wall across the coupling face (y_upper) and a ghost cell
// column that holds no particle: the MPM's air starts one cell past the FDM's end,
// so the first ghost cells' corner nodes carry mass from their neighbours only.
// T (4-3) summed the particles in the cell: e_c = 0, p = 0, and the FDM stopped
// at step 1 with "unphysical state" (the 2D blast far05 did so at 0.234 ms after
// its particles had left a ghost cell next to the wall). With e_c from the nodes
// (the support of (4-1)) and the ghost cells along the wall divided by the volume
// their corner nodes hold, the run completes and mass stays exact.
TEST(CfdmpWall2D, Fast_a_ghost_cell_without_particles_next_to_a_wall_runs) {
  const std::string yaml =
      "name: wall_2d\ntime: {end: 2.0e-4, cfl: 0.5}\n"
      "domain: {lower: [0, 0, 0], upper: [0.1, 0.05, 0.005], cells: [20, 10, 1]}\n"
      "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
      "bodies:\n"
      "  - {name: hot, material: air, density: 5.0, pressure: 1.0e6,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [0.02, 0.05, 0.005]}}}\n"
      "  - {name: zone_air, material: air, density: 1.2, pressure: 1.0e5,\n"
      "     shape: {box: {lower: [0.065, 0, 0], upper: [0.1, 0.05, 0.005]}}}\n"
      "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.06, 0.05, 0.005]}\n"
      "  mpm: {lower: [0.035, 0, 0], upper: [0.1, 0.05, 0.005]}\n  handshake_width: 5\n"
      "boundaries: {x_lower: symmetry, y_lower: symmetry, x_upper: wall, y_upper: wall,\n"
      "             z_lower: symmetry, z_upper: symmetry}\n"
      "output: {interval: 1.0e-4}\n"
      "solver: {method: cfdmp, mpm: {shape_function: linear, update: musl}}\n";
  const auto scene_file = temp_dir("wall-2d.yaml");
  std::ofstream(scene_file) << yaml;
  const auto summary = run_coupled(scene_file, temp_dir("wall-2d"));
  const double mass = summary["conservation"]["mass"]["relative_error"];
  const double energy = summary["conservation"]["energy"]["relative_error"];
  const auto steps = summary["steps"].get<std::int64_t>();
  std::printf("2D wall across the face, %lld steps: mass error %.4e, energy error %.4e\n",
              static_cast<long long>(steps), mass, energy);
  EXPECT_EQ(summary["status"], "completed");
  EXPECT_GE(steps, 20);
  EXPECT_LT(std::abs(mass), 1e-12);
}

}  // namespace
}  // namespace mpfd::coupler
