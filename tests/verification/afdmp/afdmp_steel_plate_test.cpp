// V5 (METHOD.md; T §3.4.4, Figs. 3.12–3.14): a 2D TNT charge bursts 350 mm
// from a 20 mm STEEL 1006 plate; the Mises stress at the plate's centre and
// edge tracking points in phase 3 (the FSI in the MPM, after the FDM -> MPM
// handoff) must be smooth: no oscillation driven by the handoff or the
// interface. Measures per history over phase 3: the peak, and the count of
// local extrema with prominence > 5 % of the peak (oscillation.hpp). Compared
// with pure MPM on the same scene (same particles; solver.method mpm, no FSI
// zone). The gauges follow the material (follow: material, the thesis's
// tracking points): each reads the von Mises stress of the plate particle
// bound to it at t = 0, in both runs.
// Also: every handoff conserves to <= 1e-12, and the FSI-face leak (what the
// FDM moved into the FSI zone before the trigger, discarded with its
// placeholder: afdmp_handoffs.cpp) is small against the charge's energy
// E0 V = 6.993e9 J/m^3 x (pi r^2 / 2) x 1 mm (half a cylinder: symmetry y = 0).
// Fast tier h = 10 mm, full tier h = 2.5 mm. Each writes its phase-3
// histories to $TMPDIR/mpfd-afdmp-v5-<nx>-mises.csv (bench/afdmp/plot_v5.py).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <sstream>

#include "common/config/scene_loader.hpp"
#include "coupler/run/launch.hpp"
#include "mpm_solver/followed_gauges.hpp"
#include "mpm_solver/material/solid_response.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/verification/afdmp/oscillation.hpp"
#include "tests/verification/afdmp/run_reading.hpp"
#include "tests/verification/support/scene_text.hpp"

namespace mpfd::verification {
namespace {

const std::string kPlateScene = std::string(MPFD_SOURCE_DIR) + "/configs/afdmp_steel_plate_2d.yaml";
const std::vector<std::string> kGauges = {"plate_centre", "plate_edge"};
constexpr double kProminence = 0.05;  // of the history's peak
// The plate's through-thickness reverberation period 2 d / c_L: d = 20 mm, c_L =
// sqrt((K + 4G/3) / rho) = 5.9 km/s for STEEL 1006 (K = rho c0^2 = 165 GPa, G = 81.8 GPa).
constexpr double kThicknessPeriod = 2 * 0.020 / 5890;  // [s]
constexpr double kPlateDensity = 1000;  // [kg/m^3]: steel 7890, air and products far below
// T Table 3.1 E0 times half the r = 50 mm, 1 mm thick cylinder.
const double kChargeEnergy = 6.993e9 * 0.5 * std::numbers::pi * 0.05 * 0.05 * 0.001;

/// `text` without the line that starts with `start`.
std::string without_line(std::string text, const std::string& start) {
  const std::size_t at = text.find("\n" + start);
  EXPECT_NE(at, std::string::npos) << start;
  if (at != std::string::npos) text.erase(at + 1, text.find('\n', at + 1) - at);
  return text;
}

std::filesystem::path fresh_v5_dir(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("mpfd-afdmp-v5-" + name);
  std::filesystem::remove_all(path);
  return path;
}

struct History {
  std::vector<double> time, mises;
  double peak = 0;
  int extrema = 0;
  double maxima_spacing = 0;  ///< median time between prominent maxima [s] (0: fewer than 2)
  [[nodiscard]] double end() const { return time.empty() ? 0.0 : time.back(); }
  /// Prominent extrema per second of the window (the gauge leaves the plate at
  /// different times in the two runs, so counts alone are not comparable).
  [[nodiscard]] double rate() const {
    return time.size() < 2 ? 0.0 : extrema / (time.back() - time.front());
  }
};

/// The history from `start` on, from the first sample that reads the plate to
/// the last before one that does not (a guard: a following gauge stays on its
/// plate particle unless the particle leaves the domain).
History measured(const std::vector<double>& time, const std::vector<double>& mises,
                 const std::vector<double>& density, double start) {
  History h;
  for (std::size_t k = 0; k < time.size(); ++k) {
    // The samples up to the handoff (gauges.csv rounds its time) are the FDM's.
    if (time[k] < start) continue;
    if (density[k] < kPlateDensity) {
      if (h.time.empty()) continue;
      break;
    }
    h.time.push_back(time[k]);
    h.mises.push_back(mises[k]);
  }
  EXPECT_FALSE(h.mises.empty()) << "the gauge never reads the plate after " << start << " s";
  if (h.mises.empty()) return h;
  h.peak = *std::max_element(h.mises.begin(), h.mises.end());
  h.extrema = prominent_extrema(h.mises, kProminence * h.peak);
  const auto maxima = prominent_maxima(h.mises, kProminence * h.peak);
  std::vector<double> spacing;
  for (std::size_t k = 1; k < maxima.size(); ++k)
    spacing.push_back(h.time[maxima[k]] - h.time[maxima[k - 1]]);
  if (!spacing.empty()) {
    std::nth_element(spacing.begin(), spacing.begin() + spacing.size() / 2, spacing.end());
    h.maxima_spacing = spacing[spacing.size() / 2];
  }
  return h;
}

struct V5Reading {
  std::vector<History> afdmp, mpm;  ///< per gauge, phase 3 only
  double phase3_start = 0;          ///< FDM -> MPM handoff [s]
  HandoffErrors handoffs;
  double leak_energy = 0;  ///< FSI-face leak [J]
};

/// The scene at nx x nx/2 cells, run by AFDMP and by pure MPM (driven here, the
/// gauges sampled as the coupler samples them), phase-3 histories of both.
V5Reading run_v5_both(int nx) {
  const std::string tag = std::to_string(nx);
  const std::string afdmp_text =
      replaced(read_text(kPlateScene), "cells: [1000, 500, 1]",
               "cells: [" + tag + ", " + std::to_string(nx / 2) + ", 1]");
  const auto afdmp_scene = fresh_v5_dir(tag + "-afdmp.yaml");
  std::ofstream(afdmp_scene) << afdmp_text;
  const auto afdmp_dir = fresh_v5_dir(tag + "-afdmp");
  coupler::CoupledRunOptions options;
  options.out_dir = afdmp_dir;
  options.progress = false;
  coupler::launch_run(afdmp_scene, coupler::LaunchOptions{}, options, "");

  V5Reading r;
  r.handoffs = handoff_errors(afdmp_dir / "summary.json");
  std::ifstream summary_file(afdmp_dir / "summary.json");
  const auto summary = nlohmann::json::parse(summary_file);
  for (const auto& handoff : summary.at("details").at("afdmp").at("handoffs"))
    if (handoff.at("name") == "fdm_to_mpm") {
      r.phase3_start = handoff.at("time").get<double>();
      r.leak_energy = handoff.at("fsi_face_leak").at("energy").get<double>();
    }
  EXPECT_GT(r.phase3_start, 0.0) << "no FDM -> MPM handoff";
  for (const auto& gauge : kGauges) {
    const auto csv = afdmp_dir / "gauges.csv";
    const auto mises = read_gauge_column(csv, gauge + ".mises_stress[Pa]");
    const auto density = read_gauge_column(csv, gauge + ".density[kg/m^3]");
    r.afdmp.push_back(measured(mises.time, mises.value, density.value, r.phase3_start));
  }

  const std::string mpm_text = without_line(
      without_line(replaced(afdmp_text, "method: afdmp", "method: mpm"), "  afdmp: {start: mpm}"),
      "  mpm: {lower: [0.30");
  const auto mpm_scene = fresh_v5_dir(tag + "-mpm.yaml");
  std::ofstream(mpm_scene) << replaced(mpm_text, "zones:\n", "");
  const auto scene = config::load_scene(mpm_scene);
  mpm::MpmSolver solver(scene, mpm::MpmSettings::from_scene(scene));
  mpm::FollowedGauges followed(scene.gauges, solver.particles(), mpm::binding_reach(solver.grid()));
  const double interval = scene.output.gauge_interval.value();
  std::vector<std::vector<double>> t(kGauges.size()), s(kGauges.size()), rho(kGauges.size());
  double next = 0;
  while (solver.time() < scene.time.end) {
    if (solver.time() >= next) {
      if (solver.time() >= r.phase3_start)
        for (std::size_t g = 0; g < kGauges.size(); ++g) {
          const auto p = followed.particle(scene.gauges[g].name, solver.particles());
          if (p == mpm::FollowedGauges::kLeft) continue;
          t[g].push_back(solver.time());
          s[g].push_back(mpm::von_mises_stress(solver.particles().deviator(p)));
          rho[g].push_back(solver.particles().density[p]);
        }
      while (next <= solver.time()) next += interval;
    }
    solver.advance(solver.step_toward(scene.time.end));
  }
  for (std::size_t g = 0; g < kGauges.size(); ++g)
    r.mpm.push_back(measured(t[g], s[g], rho[g], r.phase3_start));

  const auto csv = std::filesystem::temp_directory_path() / ("mpfd-afdmp-v5-" + tag + "-mises.csv");
  std::ofstream out(csv);
  out << "method,gauge,time_s,mises_pa\n";
  for (std::size_t g = 0; g < kGauges.size(); ++g)
    for (const bool afdmp : {true, false}) {
      const History& h = afdmp ? r.afdmp[g] : r.mpm[g];
      for (std::size_t k = 0; k < h.time.size(); ++k)
        out << (afdmp ? "afdmp," : "mpm,") << kGauges[g] << ',' << h.time[k] << ',' << h.mises[k]
            << '\n';
    }
  std::printf("V5 histories: %s\n", csv.c_str());
  std::printf(
      "V5 h = %.1f mm: FDM -> MPM at %.2f us, worst handoff error %.2e (round-off bound %.2e), "
      "FSI-face leak "
      "%.3e J = %.2e of the charge's %.4g J\n",
      1000.0 / nx, r.phase3_start * 1e6, r.handoffs.worst, r.handoffs.roundoff, r.leak_energy,
      r.leak_energy / kChargeEnergy, kChargeEnergy);
  for (std::size_t g = 0; g < kGauges.size(); ++g)
    std::printf(
        "  %-12s AFDMP peak %.1f MPa, %d extrema, on the plate to %.1f us | pure MPM peak %.1f "
        "MPa, %d extrema, on the plate to %.1f us\n",
        kGauges[g].c_str(), r.afdmp[g].peak / 1e6, r.afdmp[g].extrema, r.afdmp[g].end() * 1e6,
        r.mpm[g].peak / 1e6, r.mpm[g].extrema, r.mpm[g].end() * 1e6);
  return r;
}

/// The design's acceptance (notes §5.3): handoffs to round-off (1e-12, or the
/// sums' bound 2 n u on fine grids), the FSI-face leak <= 1e-4 of the charge's
/// energy, the centre yields (peak >= A = 350 MPa, T Table 3.2), each history
/// oscillating no more often than pure MPM's, and (when given) at most
/// `edge_extrema` prominent extrema at the edge. `plate_mode`: what rings is
/// the plate's own thickness mode (median spacing of the maxima within 20 % of
/// kThicknessPeriod), not an interface-driven oscillation.
void expect_acceptance(const V5Reading& r, std::optional<int> edge_extrema, bool plate_mode) {
  EXPECT_LE(r.handoffs.worst, std::max(1e-12, r.handoffs.roundoff));
  EXPECT_LE(r.leak_energy / kChargeEnergy, 1e-4);
  EXPECT_GE(r.afdmp[0].peak, 3.5e8);
  for (std::size_t g = 0; g < kGauges.size(); ++g) {
    std::printf("  %-12s prominent extrema per 100 us: AFDMP %.1f, pure MPM %.1f\n",
                kGauges[g].c_str(), r.afdmp[g].rate() * 1e-4, r.mpm[g].rate() * 1e-4);
    EXPECT_TRUE(std::isfinite(r.afdmp[g].peak)) << kGauges[g];
    EXPECT_LE(r.afdmp[g].rate(), r.mpm[g].rate()) << kGauges[g];
  }
  if (edge_extrema) {
    EXPECT_LE(r.afdmp[1].extrema, *edge_extrema);
  }
  if (plate_mode) {
    for (std::size_t g = 0; g < kGauges.size(); ++g) {
      EXPECT_NEAR(r.afdmp[g].maxima_spacing / kThicknessPeriod, 1.0, 0.2) << kGauges[g];
    }
  }
}

TEST(AfdmpSteelPlate, Fast_mises_histories_smooth_after_the_handoff) {
  // Measured (h = 10 mm, 4 particles through the plate, gauges following the
  // material): FDM -> MPM at 61.3 us, handoffs <= 5.3e-13, leak 7.0e-5 J =
  // 2.6e-9 of 27.5 kJ; centre AFDMP peak 468 MPa, 20 extrema over 61-300 us
  // vs pure MPM 534 MPa, 30; edge 542 MPa, 4 vs 622 MPa, 8. The centre's own
  // particle rings through the plate's two cells in both runs, too coarse for its
  // thickness mode: the design's "<= 4" holds at the edge only.
  expect_acceptance(run_v5_both(100), 4, false);
}

TEST(AfdmpSteelPlate, Full_mises_histories_smooth_after_the_handoff) {
  // Measured (h = 2.5 mm, gauges following the material; 373 s for AFDMP
  // loaded): FDM -> MPM at 53.5 us, handoffs 9.4e-12, leak 7e-11 of the
  // charge's energy; centre AFDMP 418 MPa, 68 extrema over 54-300 us (28 per
  // 100 us) vs pure MPM 445 MPa, 103 (42); edge 467 MPa, 57 (23) vs 483 MPa, 80
  // (33); pure MPM's twin took 370 s more.
  // The followed particle's stress rings with the plate's thickness period:
  // median spacing of the maxima 6.00 (centre) and 6.34 us (edge) against
  // 2 x 20 mm / 5.9 km/s = 6.79 us, where pure MPM's rings faster (4.20 and
  // 5.60 us: the interface-driven part). So "<= 4 extrema" (design §5.3) cannot
  // hold on a grid that resolves the plate's reverberation; asserted: no more
  // oscillation than pure MPM, and that what rings is the plate's own mode.
  expect_acceptance(run_v5_both(400), std::nullopt, true);
}

}  // namespace
}  // namespace mpfd::verification
