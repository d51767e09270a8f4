// Cost of the coupler's one-off kernels, per cell:
//   Remap/N/S: a 1D spherical profile with S shells per cell width onto an
//     N^3 grid (exact cell-shell overlaps; cost grows with the shell edges
//     crossing a cell);
//   MpmToFdm/N, FdmToMpm/N: the AFDMP handoffs of an N^3 grid with 8
//     particles per cell (T 3-3..3-8, 3-14..3-18).
// Run: build/bench/coupler/coupler_kernels_bench --benchmark_format=json

#include <benchmark/benchmark.h>

#include <vector>

#include "coupler/handoff/fdm_to_mpm.hpp"
#include "coupler/handoff/mpm_to_fdm.hpp"
#include "coupler/remap/spherical_to_cartesian.hpp"

namespace {

using mpfd::grid::UniformGrid;

UniformGrid cube(int n) {
  return UniformGrid::from_bounds({-1, -1, -1}, {1, 1, 1}, {n, n, n});
}

void Remap(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const int shells_per_cell = static_cast<int>(state.range(1));
  const UniformGrid grid = cube(n);
  const int shells = shells_per_cell * n;  // over the radius sqrt(3), cells of 2/n
  std::vector<double> edges, rho, u, e;
  std::vector<int> material;
  for (int k = 0; k <= shells; ++k) edges.push_back(1.8 * k / shells);
  for (int k = 0; k < shells; ++k) {
    rho.push_back(k < shells / 10 ? 1630.0 : 1000.0);
    u.push_back(100.0);
    e.push_back(1e5);
    material.push_back(k < shells / 10 ? 0 : 1);
  }
  const mpfd::coupler::remap::RadialProfile profile{edges, rho, u, e, material, {}, {}};
  for (auto _ : state)
    benchmark::DoNotOptimize(mpfd::coupler::remap::remap_radial_profile(grid, {0, 0, 0}, profile));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(grid.cell_count()));
}
BENCHMARK(Remap)->Args({32, 1})->Args({32, 4})->Args({64, 1})->Unit(benchmark::kMillisecond);

mpfd::coupler::handoff::ParticleSet regular(const UniformGrid& grid) {
  mpfd::coupler::handoff::ParticleSet p;
  p.resize(8 * grid.cell_count());
  std::size_t i = 0;
  for (std::size_t c = 0; c < grid.cell_count(); ++c) {
    const auto x = grid.cell_center(grid.cell_of_index(c));
    for (int k = 0; k < 8; ++k, ++i) {
      for (int a = 0; a < 3; ++a) {
        p.position[a][i] = x[a] + ((k >> a) & 1 ? 0.25 : -0.25) * grid.spacing()[a];
        p.velocity[a][i] = 10.0 * a;
      }
      p.mass[i] = 1e-3;
      p.internal_energy[i] = 200.0;
      p.material[i] = 0;
    }
  }
  return p;
}

void MpmToFdm(benchmark::State& state) {
  const UniformGrid grid = cube(static_cast<int>(state.range(0)));
  const auto particles = regular(grid);
  for (auto _ : state)
    benchmark::DoNotOptimize(mpfd::coupler::handoff::mpm_to_fdm(grid, particles.view()));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(grid.cell_count()));
}
BENCHMARK(MpmToFdm)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

void FdmToMpm(benchmark::State& state) {
  const UniformGrid grid = cube(static_cast<int>(state.range(0)));
  const auto start = mpfd::coupler::handoff::mpm_to_fdm(grid, regular(grid).view());
  const std::size_t n = grid.cell_count();
  const std::vector<double> pressure(n, 1e5), ones(n, 1.0), rho(n, 1.0), e(n, 2e5);
  const std::vector<int> material(n, 0);
  const mpfd::coupler::handoff::FdmEnd end{start.cells.view(),  pressure, material, 1, ones, rho, e,
                                           start.tracers.view()};
  for (auto _ : state) benchmark::DoNotOptimize(mpfd::coupler::handoff::fdm_to_mpm(grid, end));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(n));
}
BENCHMARK(FdmToMpm)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
