#pragma once
// The cases of the stability suite and how a run of one is judged.
//
// Time-step sweep (a case at one CFL against the same solver and case at CFL
// 0.1, the reference run): stable when the run reaches its end, every value
// is finite, and
//   * sod: the relative L1 density error against the exact solution at end / 2
//     and at the end is at most kErrorGrowth times the reference's (a stable
//     scheme's error changes little with the CFL);
//   * acoustic: the largest pressure disturbance |p - 1| at the end is at most
//     kErrorGrowth times the reference's and at most kErrorGrowth times that
//     at end / 2: an instability grows with the steps;
//   * blast_2d: the peak pressure at the end is at most kErrorGrowth times the
//     reference's and the kinetic energy within kEnergyBand of it.
// The reference run itself must be sound (reference_defect): it must reach
// its end, finite, and in the acoustic case keep the disturbance within
// kAcousticBound times the initial pulse; otherwise the case has a defect that
// no CFL cures, and the sweep reports it beside the limits.
// Hard Riemann problems: a run either matches (finite, relative L1 density
// error at most the case's tolerance) or stops with mpfd::Error; anything
// else (NaN, negative gas pressure, a large error without a message) is a
// silent failure.

#include <string>
#include <vector>

#include "tests/stability/stability_run.hpp"

namespace mpfd::stability {

inline constexpr double kErrorGrowth = 2.0;
inline constexpr double kEnergyBand = 0.1;
/// The acoustic case's initial pressure jump [Pa] and the bound on its growth.
inline constexpr double kAcousticPulse = 0.014;
inline constexpr double kAcousticBound = 5.0;
/// The reference CFL of the sweep.
inline constexpr double kReferenceCfl = 0.1;

enum class SweepCase { sod, acoustic, blast_2d };
[[nodiscard]] const char* case_name(SweepCase c);
/// The scene of `c` for `solver` at `cfl` (Sod: 100 cells; for CFDMP the
/// configs/cfdmp_sod_1d.yaml layout).
[[nodiscard]] std::string sweep_scene(SweepCase c, Solver solver, double cfl);

/// Sod's problem (1, 0, 1) | (0.125, 0, 0.1), gamma 1.4, t = 0.2 s.
[[nodiscard]] RiemannProblem sod();

/// Mean |rho - exact| at time `t` over max(rho_L, rho_R) [-].
[[nodiscard]] double relative_density_error(const Samples& s, const RiemannProblem& problem,
                                            double t);

struct SweepVerdict {
  bool stable = false;
  /// The measures ("error x1.02", "growth x0.8 amplitude x0.6", "peak x1.1
  /// energy x0.98"), or "stopped: <message>", "hung", "not finite".
  std::string text;
};
[[nodiscard]] SweepVerdict judge_sweep(SweepCase c, const Outcome& run, const Outcome& reference);
/// Empty if the reference run of `c` is sound, else what is wrong with it.
[[nodiscard]] std::string reference_defect(SweepCase c, const Outcome& reference);

/// The hard Riemann problems of issue 7 with exact solutions: pressure jumps
/// of 1e3 ... 1e6, near-vacuum rarefactions (Toro's 123 problem and a
/// stronger one), Toro's left and right halves of the Woodward-Colella blast
/// and their collision (Toro tests 3, 4, 5).
[[nodiscard]] std::vector<RiemannProblem> hard_riemann_problems();

struct RiemannVerdict {
  bool silent_failure = false;  ///< finite-less, unphysical or inaccurate without an error
  std::string text;             ///< "matches", "stopped: <message>" or what went wrong
  double error = 0.0;           ///< relative L1 density error at the end (if it ran)
};

/// The relative L1 density error hard Riemann problem `problem` (a name of
/// hard_riemann_problems() or "jwl_products_air") may have in `solver` at 200
/// cells per metre (CFDMP: 100) and finer: 1.3 x the error measured at 200,
/// rounded up (docs/stability.md). A solver whose error grows with refinement
/// fails it on the finer grid.
[[nodiscard]] double riemann_tolerance(const std::string& problem, Solver solver);

/// Judges a run of a tube case: `tolerance` on the relative L1 density error
/// (mean |rho - exact_density(x)| over [x_min, x_max] at the end, over
/// `density_scale`).
[[nodiscard]] RiemannVerdict judge_riemann(const Outcome& run, double tolerance,
                                           const std::function<double(double)>& exact_density,
                                           double density_scale, double x_min, double x_max);

/// The JWL-products-against-air tube's density at 40 us [kg/m^3]
/// (tests/verification/reference/jwl_air_tube_40us.csv, 8000 FDM cells).
[[nodiscard]] std::function<double(double)> jwl_air_tube_reference(const std::string& source_dir);

}  // namespace mpfd::stability
