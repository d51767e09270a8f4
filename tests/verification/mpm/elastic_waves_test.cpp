// Elastic waves in 1D (the P-wave modulus K + 4G/3 governs a 1D MPM column):
// * a bar fixed at x = 0 (wall) and free at x = L vibrates in its first mode
//   with the period 4 L / c_p;
// * a plane pulse leaves through non-reflecting faces (W §2.4) with a small
//   reflection, against the full reflection of free (outflow) and fixed (wall) faces.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {
namespace {

constexpr double kDensity = 1000.0;
constexpr double kBulk = 1.0e9;                                                // Pa
constexpr double kShear = 0.5e9;                                               // Pa
const double kWaveSpeed = std::sqrt((kBulk + 4.0 * kShear / 3.0) / kDensity);  // 1291 m/s

// A 1D column of `cells` cells on [0, length] made of `pieces` equal bodies,
// piece i moving at velocity(x_mid of piece i).
template <class Velocity>
std::string column_scene(double length, int cells, int pieces, const Velocity& velocity,
                         const std::string& faces) {
  std::string text = R"(
name: column
time: {end: 1.0, cfl: 0.5}
domain: {lower: [0, 0, 0], upper: [)" +
                     std::to_string(length) + ", 0.01, 0.01], cells: [" + std::to_string(cells) +
                     R"(, 1, 1]}
materials:
  solid:
    eos: {type: polynomial, rho0: 1000, A1: 1.0e9, T1: 1.0e9}
    strength: {type: elastic, shear_modulus: 0.5e9}
initial: {material: solid, density: 1000, specific_internal_energy: 0}
boundaries: )" + faces +
                     R"(
output: {interval: 1.0}
solver: {method: mpm, mpm: {bulk_viscosity_quadratic: 0, bulk_viscosity_linear: 0}}
bodies:
)";
  for (int i = 0; i < pieces; ++i) {
    const double a = length * i / pieces, b = length * (i + 1) / pieces;
    char line[256];
    std::snprintf(line, sizeof line,
                  "  - {name: p%d, material: solid, density: 1000, specific_internal_energy: 0,"
                  " velocity: [%.17g, 0, 0],\n     shape: {box: {lower: [%.17g, 0, 0], upper: "
                  "[%.17g, 0.01, 0.01]}}}\n",
                  i, velocity(0.5 * (a + b)), a, b);
    text += line;
  }
  return text;
}

double momentum_x(const MpmSolver& solver) {
  const auto& ps = solver.particles();
  double sum = 0.0;
  for (std::size_t p = 0; p < ps.size(); ++p) sum += ps.mass[p] * ps.velocity[0][p];
  return sum;
}

TEST(ElasticBarFast, FirstModePeriodIsFourLengthsOverTheWaveSpeed) {
  const double length = 1.0, v0 = 0.1;
  for (const auto shape : {config::ShapeFunction::linear, config::ShapeFunction::gimp}) {
    auto scene = config::parse_scene(
        column_scene(
            length, 100, 50,
            [&](double x) { return v0 * std::sin(std::numbers::pi * x / (2 * length)); },
            "{x_lower: wall, x_upper: outflow}"),
        "bar.yaml");
    scene.solver.mpm.shape_function = shape;
    MpmSolver solver(scene, MpmSettings::from_scene(scene));
    const double period = 4 * length / kWaveSpeed;
    // Momentum ~ cos(2 pi t / T): its zero crossings, interpolated, over 3 periods.
    std::vector<double> crossings;
    double last_t = 0.0, last_p = momentum_x(solver);
    while (solver.time() < 3.2 * period) {
      solver.advance(solver.stable_dt());
      const double p = momentum_x(solver);
      if ((p > 0) != (last_p > 0))
        crossings.push_back(last_t + (solver.time() - last_t) * last_p / (last_p - p));
      last_t = solver.time();
      last_p = p;
    }
    ASSERT_GE(crossings.size(), 5u);
    const double measured =
        2.0 * (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
    std::printf("%s: period %.6e s, analytic 4L/c_p %.6e s (%+.3f %%), %zu crossings\n",
                shape_function_name(shape), measured, period, 100 * (measured / period - 1),
                crossings.size());
    EXPECT_NEAR(measured, period, 0.01 * period);
  }
}

// A cosine-squared velocity bump splits into two pulses of half its amplitude
// that run to the faces; what is left once they have had time to leave is the
// reflection. Velocities are cell means (mass-weighted), and the middle fifth
// of the column, where the bump started, is left out: MPM leaves a standing
// grid-scale (2h) velocity pattern there (measured: cell means up to 0.038 v0,
// the same with every face), which does not travel; a reflection would be
// centred 0.2 from each face at the time of measurement.
struct PulseRun {
  double reflected_amplitude;  ///< largest cell-mean |v| left, over the outgoing peak [-]
  double energy_left;          ///< kinetic + internal energy left over the start [-]
};

/// The largest cell-mean |v| outside cells [from, to).
double largest_cell_mean_speed(const MpmSolver& solver, int cells, std::size_t from = 0,
                               std::size_t to = 0) {
  std::vector<double> momentum(static_cast<std::size_t>(cells), 0.0), mass(momentum);
  const auto& ps = solver.particles();
  for (std::size_t p = 0; p < ps.size(); ++p) {
    const auto cell = static_cast<std::size_t>(
        std::clamp(static_cast<int>(ps.position[0][p] * cells), 0, cells - 1));
    momentum[cell] += ps.mass[p] * ps.velocity[0][p];
    mass[cell] += ps.mass[p];
  }
  double largest = 0.0;
  for (std::size_t c = 0; c < mass.size(); ++c)
    if (mass[c] > 0.0 && (c < from || c >= to))
      largest = std::max(largest, std::abs(momentum[c] / mass[c]));
  return largest;
}

PulseRun run_pulse(const std::string& faces, config::ShapeFunction shape) {
  const double length = 1.0, v0 = 1.0, width = 0.2;
  const int cells = 200;
  const auto bump = [&](double x) {
    const double s = (x - 0.5) / width;
    return std::abs(s) < 0.5 ? v0 * std::pow(std::cos(std::numbers::pi * s), 2) : 0.0;
  };
  auto scene = config::parse_scene(column_scene(length, cells, 100, bump, faces), "pulse.yaml");
  scene.solver.mpm.shape_function = shape;
  MpmSolver solver(scene, MpmSettings::from_scene(scene));
  const auto energy = [&] {
    const MpmTotals t = solver.totals();
    return t.kinetic_energy + t.internal_energy;
  };
  const double e0 = energy();
  solver.advance_to(0.2 / kWaveSpeed);  // two pulses, apart, not yet at the faces
  const double peak = largest_cell_mean_speed(solver, cells);
  // Front at the face at (0.5 - 0.1) / c; tail gone by (0.5 + 0.1) / c; + 0.1 / c margin.
  solver.advance_to(0.7 / kWaveSpeed);
  return {largest_cell_mean_speed(solver, cells, 80, 120) / peak, energy() / e0};
}

TEST(NonReflectingFast, PlanePulseLeavesWithASmallReflection) {
  for (const auto shape : {config::ShapeFunction::linear, config::ShapeFunction::gimp}) {
    const PulseRun absorbing =
        run_pulse("{x_lower: non_reflecting, x_upper: non_reflecting}", shape);
    const PulseRun free_ends = run_pulse("{x_lower: outflow, x_upper: outflow}", shape);
    const PulseRun fixed_ends = run_pulse("{x_lower: wall, x_upper: wall}", shape);
    std::printf(
        "%s: reflected amplitude / energy left: non_reflecting %.4f / %.2e, outflow "
        "%.4f / %.2e, wall %.4f / %.2e\n",
        shape_function_name(shape), absorbing.reflected_amplitude, absorbing.energy_left,
        free_ends.reflected_amplitude, free_ends.energy_left, fixed_ends.reflected_amplitude,
        fixed_ends.energy_left);
    EXPECT_LT(absorbing.reflected_amplitude, 0.03);
    EXPECT_LT(absorbing.energy_left, 0.01);
    EXPECT_GT(free_ends.reflected_amplitude, 0.9);
    EXPECT_GT(fixed_ends.reflected_amplitude, 0.9);
  }
}

}  // namespace
}  // namespace mpfd::mpm
