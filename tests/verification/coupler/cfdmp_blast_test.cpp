// V6 (T §4.4.2, Fig. 4.11): a 2D charge bursting in air, run by CFDMP; the
// tracking points at the same distance from the charge, one in the FDM zone
// (x < 0) and one in the MPM zone (x > 0), must read the same history — no
// interface effect. Fast tier: configs/cfdmp_blast_2d_coarse.yaml (h = 5 mm,
// 60 us). Full tier: configs/cfdmp_blast_2d.yaml (the thesis's h = 2 mm).
// Measures, per gauge: the peak overpressure max(p) - p(0) and the arrival
// time, when p - p(0) first exceeds 10 % of the peak (linear interpolation
// between samples). One cell's travel time h / U uses the shock speed U that
// a pure-FDM run measures between the FDM point and one two cells further out.
// Every CFDMP gauge is also compared with a pure-FDM run of the same scene.
//
// Two charges: (a) the scene's TNT products (JWL), (b) the same cylinder of
// ideal-gas air with the products' density and specific internal energy
// (one fluid: isolates the face from the choice of an injected particle's
// material, coupler/run/injected_material). The MPM gauge reads the particle
// nearest to its point, up to h/4 from it (0.25 h / U of arrival).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/config/scene_loader.hpp"
#include "common/io/hdf5_file.hpp"
#include "coupler/run/launch.hpp"
#include "fdm_solver/standalone_run.hpp"
#include "tests/verification/support/scene_text.hpp"

namespace mpfd::coupler {
namespace {

using verification::read_text;
using verification::replaced_all;

const std::string kConfigs = std::string(MPFD_SOURCE_DIR) + "/configs/";

std::filesystem::path temp_path(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("mpfd-cfdmp-blast-" + name);
  std::filesystem::remove_all(path);
  return path;
}

struct GaugeReading {
  double peak_overpressure = 0;  ///< Pa
  double arrival = 0;            ///< s
};

GaugeReading read_gauge(const std::filesystem::path& dir, const std::string& gauge) {
  const io::Hdf5File file(dir / "gauges.h5", io::Hdf5File::Mode::read);
  const auto t = file.read_dataset("/time").values;
  const auto p = file.read_dataset("/gauges/" + gauge + "/pressure").values;
  GaugeReading r;
  const double p0 = p.front();
  r.peak_overpressure = *std::max_element(p.begin(), p.end()) - p0;
  const double threshold = p0 + 0.1 * r.peak_overpressure;
  for (std::size_t k = 1; k < p.size(); ++k)
    if (p[k] > threshold) {
      r.arrival = t[k - 1] + (threshold - p[k - 1]) / (p[k] - p[k - 1]) * (t[k] - t[k - 1]);
      break;
    }
  return r;
}

struct Comparison {
  GaugeReading fdm_zone, mpm_zone, pure_fdm_at_fdm_point, pure_fdm_at_mpm_point;
  double cell_travel = 0;  ///< h / U [s]
};

/// Runs `yaml` by CFDMP and by the FDM alone (plus a gauge two cells beyond
/// p1_fdm for the shock speed) and reads gauges p1_fdm and p2_mpm of both.
Comparison run_both(const std::string& name, const std::string& yaml) {
  const auto scene_file = temp_path(name + ".yaml");
  std::ofstream(scene_file) << yaml;
  const auto coupled = temp_path(name + "-cfdmp");
  LaunchOptions launch;  // both solvers in this process
  CoupledRunOptions options;
  options.out_dir = coupled;
  options.progress = false;
  launch_run(scene_file, launch, options, "");

  auto scene = config::load_scene(scene_file);
  const auto& p1 = scene.gauges[0];
  const double h = (scene.domain.upper[0] - scene.domain.lower[0]) / scene.domain.cells[0];
  scene.gauges.push_back({"p1_out", {p1.position[0] - 2 * h, p1.position[1], p1.position[2]}});
  scene.zones.reset();
  scene.solver.method = config::Method::fdm;
  const auto pure = temp_path(name + "-fdm");
  fdm::run_standalone(scene, {.scene_file = scene_file, .out_dir = pure});

  Comparison c{read_gauge(coupled, "p1_fdm"), read_gauge(coupled, "p2_mpm"),
               read_gauge(pure, "p1_fdm"), read_gauge(pure, "p2_mpm")};
  const double speed =
      2 * h / (read_gauge(pure, "p1_out").arrival - c.pure_fdm_at_fdm_point.arrival);
  c.cell_travel = h / speed;
  std::printf(
      "%s: CFDMP p1 (FDM zone) peak %.3f MPa arrival %.2f us | p2 (MPM zone) peak %.3f MPa "
      "arrival %.2f us\n  pure FDM p1 peak %.3f MPa arrival %.2f us | p2 peak %.3f MPa arrival "
      "%.2f us\n  shock speed %.0f m/s, h / U = %.2f us\n",
      name.c_str(), c.fdm_zone.peak_overpressure / 1e6, c.fdm_zone.arrival * 1e6,
      c.mpm_zone.peak_overpressure / 1e6, c.mpm_zone.arrival * 1e6,
      c.pure_fdm_at_fdm_point.peak_overpressure / 1e6, c.pure_fdm_at_fdm_point.arrival * 1e6,
      c.pure_fdm_at_mpm_point.peak_overpressure / 1e6, c.pure_fdm_at_mpm_point.arrival * 1e6, speed,
      c.cell_travel * 1e6);
  return c;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

TEST(CfdmpBlast, Fast_gas_charge_gauges_agree_across_the_zone_face) {
  const auto yaml = replaced_all(read_text(kConfigs + "cfdmp_blast_2d_coarse.yaml"),
                                 "    material: tnt\n", "    material: air\n");
  const auto c = run_both("gas", yaml);
  // Measured (uGIMP MPM, outer nodes fed): p1 54.44 / p2 54.84 MPa (+0.7 %), arrival
  // 17.68 / 18.68 us (1.00 us = 0.84 h / U, h / U = 1.19 us; linear shapes: 0.39 us,
  // uGIMP's wider particle smears the shock on this grid: a 16 % margin to the
  // arrival bound); pure FDM at p2 54.21 MPa (CFDMP +1.2 %), 17.68 us. Without the
  // outer nodes: p2 54.77 MPa.
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.fdm_zone.peak_overpressure), 0.05);
  EXPECT_LT(std::abs(c.mpm_zone.arrival - c.fdm_zone.arrival), c.cell_travel);
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.pure_fdm_at_mpm_point.peak_overpressure),
            0.05);
  EXPECT_LT(std::abs(c.mpm_zone.arrival - c.pure_fdm_at_mpm_point.arrival), c.cell_travel);
  // The FDM zone does not feel the coupling.
  EXPECT_LT(relative(c.fdm_zone.peak_overpressure, c.pure_fdm_at_fdm_point.peak_overpressure),
            0.01);
}

TEST(CfdmpBlast, Fast_tnt_charge_gauges_agree_across_the_zone_face) {
  const auto c = run_both("tnt", read_text(kConfigs + "cfdmp_blast_2d_coarse.yaml"));
  // Measured (uGIMP MPM, outer nodes fed): p1 51.14 / p2 52.12 MPa (+1.9 %), arrival
  // 15.70 / 16.61 us (0.91 us = 0.83 h / U, h / U = 1.10 us; linear shapes: 0.57 us);
  // pure FDM at p2 51.82 MPa (CFDMP +0.6 %), 15.73 us. Without the outer nodes:
  // p2 52.24 MPa. Before the injected particles' material was chosen by pressure
  // (all air), p2 read 64.69 MPa (+26 %). The arrival bound has a 17 % margin.
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.fdm_zone.peak_overpressure), 0.05);
  EXPECT_LT(std::abs(c.mpm_zone.arrival - c.fdm_zone.arrival), c.cell_travel);
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.pure_fdm_at_mpm_point.peak_overpressure),
            0.05);
  EXPECT_LT(std::abs(c.mpm_zone.arrival - c.pure_fdm_at_mpm_point.arrival), c.cell_travel);
  EXPECT_LT(relative(c.fdm_zone.peak_overpressure, c.pure_fdm_at_fdm_point.peak_overpressure),
            0.01);
}

TEST(CfdmpBlast, Full_thesis_grid_gas_charge_gauges_agree) {
  const auto yaml = replaced_all(read_text(kConfigs + "cfdmp_blast_2d.yaml"), "    material: tnt\n",
                                 "    material: air\n");
  const auto c = run_both("full-gas", yaml);
  // Measured (h = 2 mm, uGIMP MPM, 24 s): p1 53.25 / p2 51.50 MPa (-3.3 %),
  // arrival 17.05 / 17.24 us (0.19 us; h / U = 0.45 us); pure FDM at p2
  // 53.05 MPa (CFDMP -2.9 %). The window's peak is the charge gas arriving
  // behind the shock; with linear shapes the MPM zone held it 9.0 % low (the
  // flow's transverse noise, docs/coupler.md "Where the tail is lost"), so
  // 15 % was asserted; uGIMP meets the thesis's 5 %.
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.fdm_zone.peak_overpressure), 0.05);
  EXPECT_LT(std::abs(c.mpm_zone.arrival - c.fdm_zone.arrival), c.cell_travel);
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.pure_fdm_at_mpm_point.peak_overpressure),
            0.05);
  EXPECT_LT(relative(c.fdm_zone.peak_overpressure, c.pure_fdm_at_fdm_point.peak_overpressure),
            0.01);
}

TEST(CfdmpBlast, Full_thesis_grid_tnt_charge_gauges_agree) {
  const auto c = run_both("full-tnt", read_text(kConfigs + "cfdmp_blast_2d.yaml"));
  // Measured (h = 2 mm, uGIMP MPM, 38 s): p1 46.53 / p2 45.67 MPa (-1.8 %),
  // arrival 15.35 / 15.69 us (0.34 us; h / U = 0.43 us); pure FDM p1 46.34,
  // p2 46.28 MPa (CFDMP p2 -1.3 %). Linear shapes: p2 45.04 MPa (-3.2 %).
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.fdm_zone.peak_overpressure), 0.05);
  EXPECT_LT(std::abs(c.mpm_zone.arrival - c.fdm_zone.arrival), c.cell_travel);
  EXPECT_LT(relative(c.mpm_zone.peak_overpressure, c.pure_fdm_at_mpm_point.peak_overpressure),
            0.05);
  EXPECT_LT(relative(c.fdm_zone.peak_overpressure, c.pure_fdm_at_fdm_point.peak_overpressure),
            0.01);
}

}  // namespace
}  // namespace mpfd::coupler
