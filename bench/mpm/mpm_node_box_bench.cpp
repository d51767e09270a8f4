// Cost of the MPM side of a CFDMP step outside Advance (issue 5's coupling
// overhead, docs/coupler.md): the ghost_nodes export's particle-to-node map
// of one node box, against one whole MPM step on the same particles, in one
// run so that the ratio is measured under the same load (the machine is shared).
//   Step/<shape>: one advance of a V6-like MPM zone, 25 x 250 cells of 2 mm,
//     2 x 2 particles per cell, a hot band in its middle so the particles
//     leave their lattice (the summation order then matters, as in a run);
//     shape 0 linear, 1 uGIMP.
//   MappedStep/<shape>: the same step as a coupled run takes it now: the
//     ghost_nodes export maps it early (MpmSolver::map_next_step), the box is
//     read from that map, and the advance starts from it.
//   GhostNodeBox/<shape>: MpmSolver::map_particles_to_node_box on the nodes
//     of 3 ghost cells across the zone (CfdmpStep's box for w = 5), after the
//     same warm-up; counters give the particles reaching it.
// Run: build/bench/mpm/mpm_node_box_bench --benchmark_format=json

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace {

mpfd::config::Scene zone(std::int64_t shape) {
  return mpfd::config::parse_scene(
      "name: node_box_bench\ntime: {end: 1.0, cfl: 0.3}\n"
      "domain: {lower: [0, 0, 0], upper: [0.05, 0.5, 0.002], cells: [25, 250, 1]}\n"
      "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
      "bodies:\n"
      "  - {name: low, material: air, density: 1.2, pressure: 1.0e5,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [0.05, 0.2, 0.002]}}}\n"
      "  - {name: hot, material: air, density: 1.2, pressure: 1.0e6,\n"
      "     shape: {box: {lower: [0, 0.2, 0], upper: [0.05, 0.3, 0.002]}}}\n"
      "  - {name: high, material: air, density: 1.2, pressure: 1.0e5,\n"
      "     shape: {box: {lower: [0, 0.3, 0], upper: [0.05, 0.5, 0.002]}}}\n"
      "boundaries: {x_lower: wall, x_upper: wall, y_lower: wall, y_upper: wall}\n"
      "output: {interval: 1.0}\nsolver: {method: mpm, mpm: {shape_function: " +
          std::string(shape == 0 ? "linear" : "gimp") + "}}\n",
      "node_box_bench.yaml");
}

void warm_up(mpfd::mpm::MpmSolver& solver) {
  for (int step = 0; step < 20; ++step) solver.advance(solver.stable_dt());
}

void Step(benchmark::State& state) {
  const auto scene = zone(state.range(0));
  mpfd::mpm::MpmSolver solver(scene, mpfd::mpm::MpmSettings::from_scene(scene));
  warm_up(solver);
  for (auto _ : state) solver.advance(solver.stable_dt());
  state.counters["particles"] = static_cast<double>(solver.particles().size());
}
BENCHMARK(Step)->Arg(0)->Arg(1)->ArgName("shape")->Iterations(200)->Unit(benchmark::kMicrosecond);

void MappedStep(benchmark::State& state) {
  const auto scene = zone(state.range(0));
  mpfd::mpm::MpmSolver solver(scene, mpfd::mpm::MpmSettings::from_scene(scene));
  warm_up(solver);
  mpfd::mpm::NodeBoxMap box;
  for (auto _ : state) {
    solver.map_next_step({5, 0, 0}, {9, 251, 1});
    solver.read_next_step_box({5, 0, 0}, {9, 251, 1}, box);
    solver.advance(solver.stable_dt());
  }
  state.counters["particles"] = static_cast<double>(solver.particles().size());
}
BENCHMARK(MappedStep)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("shape")
    ->Iterations(200)
    ->Unit(benchmark::kMicrosecond);

void GhostNodeBox(benchmark::State& state) {
  const auto scene = zone(state.range(0));
  mpfd::mpm::MpmSolver solver(scene, mpfd::mpm::MpmSettings::from_scene(scene));
  warm_up(solver);
  mpfd::mpm::NodeBoxMap box;
  for (auto _ : state) {
    solver.map_particles_to_node_box({5, 0, 0}, {9, 251, 1}, box);
    benchmark::DoNotOptimize(box.mass.data());
  }
  state.counters["particles"] = static_cast<double>(solver.particles().size());
  state.counters["reaching"] = static_cast<double>(box.reaching.size());
}
BENCHMARK(GhostNodeBox)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("shape")
    ->Iterations(2000)
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
