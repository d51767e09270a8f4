// Cost of one MPM step per update scheme, in one run so that the ratio
// usavg / musl is measured under the same load (the machine is shared):
//   Step/<update>/<shape>: a 2D gas box, 128 x 128 cells, 4 particles per
//     cell, a strip at 10x the pressure in its middle, walls round it,
//     update 0 musl, 1 usl, 2 usavg; shape 0 linear, 1 GIMP.
// Compare the CPU time per iteration of /2/s with /0/s (docs/stability.md).
// Run: build/bench/mpm/mpm_update_bench --benchmark_format=json

#include <benchmark/benchmark.h>

#include <string>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace {

using mpfd::config::MpmUpdate;
using mpfd::config::ShapeFunction;

mpfd::config::Scene gas_box() {
  return mpfd::config::parse_scene(
      "name: update_bench\ntime: {end: 1.0, cfl: 0.3}\n"
      "domain: {lower: [0, 0, 0], upper: [1, 1, 0.0078125], cells: [128, 128, 1]}\n"
      "materials:\n  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
      "initial: {material: air, density: 1.2, pressure: 1.0e5}\n"
      "bodies:\n"
      "  - {name: left, material: air, density: 1.2, pressure: 1.0e5,\n"
      "     shape: {box: {lower: [0, 0, 0], upper: [0.4, 1, 0.0078125]}}}\n"
      "  - {name: hot, material: air, density: 1.2, pressure: 1.0e6,\n"
      "     shape: {box: {lower: [0.4, 0, 0], upper: [0.6, 1, 0.0078125]}}}\n"
      "  - {name: right, material: air, density: 1.2, pressure: 1.0e5,\n"
      "     shape: {box: {lower: [0.6, 0, 0], upper: [1, 1, 0.0078125]}}}\n"
      "boundaries: {x_lower: wall, x_upper: wall, y_lower: wall, y_upper: wall}\n"
      "output: {interval: 1.0}\nsolver: {method: mpm}\n",
      "update_bench.yaml");
}

void Step(benchmark::State& state) {
  const MpmUpdate updates[] = {MpmUpdate::musl, MpmUpdate::usl, MpmUpdate::usavg};
  const auto scene = gas_box();
  auto settings = mpfd::mpm::MpmSettings::from_scene(scene);
  settings.update = updates[state.range(0)];
  settings.shape_function = state.range(1) == 0 ? ShapeFunction::linear : ShapeFunction::gimp;
  mpfd::mpm::MpmSolver solver(scene, settings);
  solver.advance(solver.stable_dt());  // warm-up: the grid's arrays reach their size
  for (auto _ : state) solver.advance(solver.stable_dt());
  state.counters["particles"] = static_cast<double>(solver.particles().size());
}
BENCHMARK(Step)
    ->ArgsProduct({{0, 1, 2}, {0, 1}})
    ->ArgNames({"update", "shape"})
    ->Iterations(100)  // every scheme times the same 100 steps from the same start
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
