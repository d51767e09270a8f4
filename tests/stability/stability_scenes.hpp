#pragma once
// The scenes of the stability suite (issue 7), written as scene-file text so
// that they go through the same parser as a user's: a 1D tube with a Riemann
// problem, an acoustic pulse, a JWL-products-against-air tube and a small 2D
// blast, each for FDM, MPM or CFDMP. A scene carries `cfl` as time.cfl, or no
// time.cfl (each solver's default) if it is absent; the time-step sweeps give
// the FDM and MPM solvers values above 1 through their APIs.

#include <optional>
#include <string>

#include "tests/verification/support/primitive_state.hpp"

namespace mpfd::stability {

/// Which solver runs a case. MPM with the linear or the GIMP shape functions.
enum class Solver { fdm, mpm_linear, mpm_gimp, cfdmp };

[[nodiscard]] const char* solver_name(Solver solver);

/// A Riemann problem of an ideal gas on [0, 1] m with the diaphragm at 0.5 m.
struct RiemannProblem {
  std::string name;
  verification::PrimitiveState left;
  verification::PrimitiveState right;
  double gamma = 1.4;
  double end = 0.2;  ///< [s]
};

/// How far the tube reaches beyond [0, 1] m on each side [m]: what the open
/// ends do (an MPM outflow face is a free surface, gas streams out of or
/// away from it) stays out of [0, 1] m, where errors are measured.
inline constexpr double kTubeMargin = 1.5;

/// The tube scene of `problem` with `cells` cells per metre on
/// [-kTubeMargin, 1 + kTubeMargin] m: both states are bodies (the MPM fills
/// no background), outflow ends. For CFDMP the FDM zone is x < 0.65 m, the
/// MPM zone x > 0.6 m, w = 5 cells, as configs/cfdmp_sod_1d.yaml. Snapshots
/// at end / 2 and end.
[[nodiscard]] std::string tube_scene(const RiemannProblem& problem, int cells, Solver solver,
                                     std::optional<double> cfl);

/// A small acoustic pulse (density 1.01, pressure 1.014 on [0.45, 0.55] m in
/// gas at rest at 1, 1; gamma 1.4) between walls on [0, 1] m, 100 cells, to
/// 5 s: the waves cross the tube about 6 times, 600 to 6000 steps. A linearly
/// unstable step shows here as growth with the steps. CFDMP zones as in
/// tube_scene().
[[nodiscard]] std::string acoustic_scene(Solver solver, std::optional<double> cfl);

/// JWL detonation products (T Table 3.1, 2227 kg/m^3, 21 GPa) on [0, 0.1] m
/// against air (1.225 kg/m^3, 101 kPa) on [0.1, 0.5] m, 500 cells, to 40 us:
/// configs/jwl_air_tube.yaml with the air as a body too.
[[nodiscard]] std::string jwl_air_tube_scene(Solver solver, std::optional<double> cfl);

/// A cylinder of TNT products (radius 25 mm, T Table 3.1, E0 / rho0) in air,
/// quarter domain 0.2 m x 0.2 m with 40 x 40 cells (symmetry at x = 0 and
/// y = 0, outflow elsewhere), to 40 us. For CFDMP: the FDM zone is x < 0.15 m,
/// the MPM zone x > 0.125 m.
[[nodiscard]] std::string blast_2d_scene(Solver solver, std::optional<double> cfl);

}  // namespace mpfd::stability
