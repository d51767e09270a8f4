#include "tests/stability/stability_scenes.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace mpfd::stability {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

/// The `solver:` line; CFDMP also needs `zones`, which the caller writes. The MPM's
/// update is left to its default (usavg), so that the CFL map is the default's.
std::string solver_section(Solver solver) {
  switch (solver) {
    case Solver::fdm:
      return "solver: {method: fdm}\n";
    case Solver::mpm_linear:
      return "solver: {method: mpm, mpm: {shape_function: linear}}\n";
    case Solver::mpm_gimp:
      return "solver: {method: mpm, mpm: {shape_function: gimp}}\n";
    case Solver::cfdmp:
      break;
  }
  return "solver: {method: cfdmp, mpm: {shape_function: linear}}\n";
}

/// The time section: end time and, if given, the CFL.
std::string time_text(double end, std::optional<double> cfl) {
  return "time: {end: " + number(end) + (cfl ? ", cfl: " + number(*cfl) : std::string()) + "}\n";
}

std::string state_text(const verification::PrimitiveState& s) {
  return "density: " + number(s.density) + ", velocity: [" + number(s.velocity) +
         ", 0, 0], pressure: " + number(s.pressure);
}

// T Table 3.1 (E0 = 6993 mJ/mm^3, A = 3.712e5 MPa, B = 3.21e3 MPa).
constexpr const char* kAirAndTnt =
    "materials:\n"
    "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
    "  tnt:\n"
    "    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3,\n"
    "          E0: 6.993e9}\n";

}  // namespace

const char* solver_name(Solver solver) {
  switch (solver) {
    case Solver::fdm:
      return "fdm";
    case Solver::mpm_linear:
      return "mpm_linear";
    case Solver::mpm_gimp:
      return "mpm_gimp";
    case Solver::cfdmp:
      break;
  }
  return "cfdmp";
}

std::string tube_scene(const RiemannProblem& problem, int cells, Solver solver,
                       std::optional<double> cfl) {
  const std::string side = "0.01";
  const std::string lower = number(-kTubeMargin), upper = number(1.0 + kTubeMargin);
  const int total = static_cast<int>(std::lround(cells * (1.0 + 2.0 * kTubeMargin)));
  std::string text = "name: " + problem.name + "\n" + time_text(problem.end, cfl) +
                     "domain: {lower: [" + lower + ", 0, 0], upper: [" + upper + ", " + side +
                     ", " + side + "], cells: [" + std::to_string(total) + ", 1, 1]}\n" +
                     "materials:\n  gas: {eos: {type: ideal_gas, gamma: " + number(problem.gamma) +
                     "}}\n" + "initial: {material: gas, " + state_text(problem.right) + "}\n" +
                     "bodies:\n"
                     "  - {name: left, material: gas, " +
                     state_text(problem.left) + ",\n     shape: {box: {lower: [" + lower +
                     ", 0, 0], upper: [0.5, " + side + ", " + side + "]}}}\n" +
                     "  - {name: right, material: gas, " + state_text(problem.right) +
                     ",\n     shape: {box: {lower: [0.5, 0, 0], upper: [" + upper + ", " + side +
                     ", " + side + "]}}}\n" +
                     "boundaries: {x_lower: outflow, x_upper: outflow, y_lower: symmetry, "
                     "y_upper: symmetry, z_lower: symmetry, z_upper: symmetry}\n" +
                     "output: {interval: " + number(0.5 * problem.end) +
                     ", fields: [density, velocity, pressure]}\n" + solver_section(solver);
  if (solver == Solver::cfdmp)
    text += "zones:\n  fdm: {lower: [" + lower + ", 0, 0], upper: [0.65, " + side + ", " + side +
            "]}\n  mpm: {lower: [0.6, 0, 0], upper: [" + upper + ", " + side + ", " + side +
            "]}\n  handshake_width: 5\n";
  return text;
}

std::string acoustic_scene(Solver solver, std::optional<double> cfl) {
  std::string text =
      "name: acoustic_pulse\n" + time_text(5.0, cfl) +
      "domain: {lower: [0, 0, 0], upper: [1, 0.01, 0.01], cells: [100, 1, 1]}\n"
      "materials:\n  gas: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: {material: gas, density: 1, pressure: 1}\n"
      "bodies:\n"
      "  - {name: still, material: gas, density: 1, pressure: 1,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [1, 0.01, 0.01]}}}\n"
      "  - {name: pulse, material: gas, density: 1.01, pressure: 1.014,\n"
      "     shape: {box: {lower: [0.45, 0, 0], upper: [0.55, 0.01, 0.01]}}}\n"
      "boundaries: {x_lower: wall, x_upper: wall, y_lower: symmetry, y_upper: symmetry,\n"
      "             z_lower: symmetry, z_upper: symmetry}\n"
      "output: {interval: 2.5, fields: [density, velocity, pressure]}\n" +
      solver_section(solver);
  if (solver == Solver::cfdmp)
    text +=
        "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.65, 0.01, 0.01]}\n"
        "  mpm: {lower: [0.6, 0, 0], upper: [1, 0.01, 0.01]}\n  handshake_width: 5\n";
  return text;
}

std::string jwl_air_tube_scene(Solver solver, std::optional<double> cfl) {
  std::string text =
      "name: jwl_air_tube\n" + time_text(4.0e-5, cfl) +
      "domain: {lower: [0, 0, 0], upper: [0.5, 0.001, 0.001], cells: [500, 1, 1]}\n" +
      std::string(kAirAndTnt) +
      "initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}\n"
      "bodies:\n"
      "  - {name: products, material: tnt, density: 2227.47, pressure: 2.0984e10,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [0.1, 0.001, 0.001]}}}\n"
      "  - {name: air, material: air, density: 1.225, specific_internal_energy: 2.0685e5,\n"
      "     shape: {box: {lower: [0.1, 0, 0], upper: [0.5, 0.001, 0.001]}}}\n"
      "boundaries: {x_lower: wall, x_upper: outflow, y_lower: symmetry, y_upper: symmetry,\n"
      "             z_lower: symmetry, z_upper: symmetry}\n"
      "output: {interval: 2.0e-5, fields: [density, velocity, pressure]}\n" +
      solver_section(solver);
  if (solver == Solver::cfdmp)
    text +=
        "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.2, 0.001, 0.001]}\n"
        "  mpm: {lower: [0.195, 0, 0], upper: [0.5, 0.001, 0.001]}\n  handshake_width: 5\n";
  return text;
}

std::string blast_2d_scene(Solver solver, std::optional<double> cfl) {
  std::string text =
      "name: blast_2d_small\n" + time_text(4.0e-5, cfl) +
      "domain: {lower: [0, 0, 0], upper: [0.2, 0.2, 0.005], cells: [40, 40, 1]}\n" +
      std::string(kAirAndTnt) +
      "initial: {material: air, density: 1.225, specific_internal_energy: 2.0685e5}\n"
      "bodies:\n"
      "  - {name: air, material: air, density: 1.225, specific_internal_energy: 2.0685e5,\n"
      "     shape: {box: {lower: [" +
      std::string(solver == Solver::cfdmp ? "0.125" : "0") +
      ", 0, 0], upper: [0.2, 0.2, 0.005]}}}\n"
      "  - {name: products, material: tnt, density: 1630, specific_internal_energy: 4.2902e6,\n"
      "     shape: {cylinder: {base: [0, 0, 0], axis: [0, 0, 1], radius: 0.025, length: "
      "0.005}}}\n"
      "boundaries: {x_lower: symmetry, y_lower: symmetry, x_upper: outflow, y_upper: outflow,\n"
      "             z_lower: symmetry, z_upper: symmetry}\n"
      "output: {interval: 2.0e-5, fields: [density, velocity, pressure]}\n" +
      solver_section(solver);
  if (solver == Solver::cfdmp)
    text +=
        "zones:\n  fdm: {lower: [0, 0, 0], upper: [0.15, 0.2, 0.005]}\n"
        "  mpm: {lower: [0.125, 0, 0], upper: [0.2, 0.2, 0.005]}\n  handshake_width: 5\n";
  return text;
}

}  // namespace mpfd::stability
