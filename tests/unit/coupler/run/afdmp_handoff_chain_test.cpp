// The kernels of the AFDMP handoffs chained as the run loop will chain them
// (design §3.5 H1 step 3 and H2 step 2), with the audit of §3.6: the wire
// arrays the coupler sends equal, to round-off, what it received plus the
// placeholder it booked.
#include <gtest/gtest.h>

#include <vector>

#include "common/config/scene_loader.hpp"
#include "coupler/handoff/fdm_to_mpm.hpp"
#include "coupler/handoff/mpm_to_fdm.hpp"
#include "coupler/handoff/placeholder.hpp"
#include "coupler/handoff/sub_grid.hpp"
#include "coupler/run/afdmp_layout.hpp"
#include "coupler/run/handoff_audit.hpp"
#include "tests/unit/coupler/handoff/handoff_test_support.hpp"

namespace mpfd::coupler {
namespace {

// 20 x 10 cells of 10 mm, FSI zone x in [0.14, 0.2] m (cells 14..19).
constexpr const char* kScene =
    "name: chain\ntime: {end: 1.0e-4}\n"
    "domain: {lower: [0, 0, 0], upper: [0.2, 0.1, 0.01], cells: [20, 10, 1]}\n"
    "materials:\n"
    "  air: {eos: {type: ideal_gas, gamma: 1.4}}\n"
    "  tnt:\n"
    "    eos: {type: jwl, rho0: 1630, A: 3.712e11, B: 3.21e9, R1: 4.15, R2: 0.95, omega: 0.3,"
    " E0: 6.993e9}\n"
    "    explosive: {detonation_velocity: 6930}\n"
    "initial: {material: air, density: 1.225, pressure: 1.0e5}\n"
    "charges:\n"
    "  - {name: c, material: tnt, detonation_point: [0, 0, 0.005],\n"
    "     shape: {cylinder: {base: [0, 0, 0], axis: [0, 0, 1], radius: 0.02, length: 0.01}}}\n"
    "output: {interval: 1.0e-5}\nsolver: {method: afdmp}\n"
    "zones:\n  mpm: {lower: [0.14, 0, 0], upper: [0.2, 0.1, 0.01], activation_pressure: 2.0e5}\n";

constexpr double kAudit = 1e-12;  // design §3.6

struct Chain {
  config::Scene scene = config::parse_scene(kScene, "chain.yaml");
  AfdmpLayout layout = make_afdmp_layout(scene);
  grid::UniformGrid whole =
      grid::UniformGrid::from_bounds(scene.domain.lower, scene.domain.upper, scene.domain.cells);
  handoff::CellBox fluid_box = to_cell_box(layout.fluid_cells);
  handoff::CellBox fsi_box = to_cell_box(*layout.fsi_cells);
  grid::UniformGrid fluid = handoff::sub_grid(whole, fluid_box);
};

struct WireCells {
  std::vector<double> rho, momentum, energy;
};

WireCells to_wire(const grid::Index3& cells, const handoff::ConservedView& c) {
  const std::size_t n = c.density.size();
  WireCells w{std::vector<double>(n), std::vector<double>(3 * n), std::vector<double>(n)};
  handoff::grid_to_wire_order(cells, c.density, w.rho);
  handoff::grid_to_wire_vectors(cells, c.momentum, w.momentum);
  handoff::grid_to_wire_order(cells, c.total_energy, w.energy);
  return w;
}

TEST(AfdmpHandoffChain, MpmToFdmSendsTheFluidParticlesPlusTheBookedPlaceholder) {
  const Chain k;
  const handoff::ParticleSet particles = handoff::test::random_particles(k.fluid, 3000, 11u);
  const handoff::FdmStart start = handoff::mpm_to_fdm(k.fluid, particles.view());

  handoff::ConservedCells cells;
  cells.assign(k.whole.cell_count());
  handoff::embed_cells(k.whole, k.fluid_box, start.cells.view(), cells);
  handoff::ConservedCells placeholder;
  placeholder.assign(k.whole.cell_count());
  const handoff::AmbientState air = handoff::ambient_state(k.scene);
  handoff::fill_ambient_cells(k.whole, k.fsi_box, air, cells);
  handoff::fill_ambient_cells(k.whole, k.fsi_box, air, placeholder);
  handoff::TracerPoints tracers = start.tracers;
  handoff::append_regular_tracers(k.whole, k.fsi_box, air.material,
                                  k.scene.solver.fdm.tracers_per_axis, tracers);
  EXPECT_EQ(tracers.size(), particles.size() + 60u * 4u);  // 6 x 10 FSI cells, 2^2 tracers each

  const WireCells wire = to_wire(k.whole.cells(), cells.view());
  const double v = k.whole.cell_volume();
  const Conserved sent = wire_cell_conserved(wire.rho, wire.momentum, wire.energy, v);
  const Conserved received = particle_conserved(particles.view());
  const Conserved booked = cell_conserved(placeholder.view(), v);
  EXPECT_NEAR(booked.mass, 60.0 * 1.225 * v, 1e-14 * booked.mass);
  const ConservedError e = relative_error(received, difference(sent, booked));
  RecordProperty("relative_error", e.summary().dump());
  EXPECT_LE(e.mass, kAudit);
  EXPECT_LE(e.momentum, kAudit);
  EXPECT_LE(e.energy, kAudit);
}

// H2: the FDM exports fluid_cells in the fluid box's wire order; the coupler
// turns them back to grid order, builds particles on the fluid grid, and
// every particle lies in the fluid zone, the volumes fill it, and the
// particles carry what the wire carried.
TEST(AfdmpHandoffChain, FdmToMpmOnTheFluidZoneKeepsWhatTheWireCarried) {
  const Chain k;
  const handoff::ParticleSet seed = handoff::test::random_particles(k.whole, 5000, 3u);
  const handoff::FdmStart state = handoff::mpm_to_fdm(k.whole, seed.view());  // a whole-grid state
  const std::size_t n = k.fluid_box.count();
  handoff::ConservedCells box;
  box.assign(n);
  handoff::extract_cells(k.whole, k.fluid_box, state.cells.density, box.density);
  for (int a = 0; a < 3; ++a)
    handoff::extract_cells(k.whole, k.fluid_box, state.cells.momentum[a], box.momentum[a]);
  handoff::extract_cells(k.whole, k.fluid_box, state.cells.total_energy, box.total_energy);
  const WireCells wire = to_wire(k.fluid.cells(), box.view());  // what fluid_cells exports

  handoff::ConservedCells back;
  back.assign(n);
  handoff::wire_to_grid_order(k.fluid.cells(), wire.rho, back.density);
  handoff::wire_to_grid_vectors(k.fluid.cells(), wire.momentum,
                                {back.momentum[0], back.momentum[1], back.momentum[2]});
  handoff::wire_to_grid_order(k.fluid.cells(), wire.energy, back.total_energy);
  EXPECT_EQ(back.density, box.density);
  EXPECT_EQ(back.momentum, box.momentum);

  const std::vector<double> pressure(n, 1e5);
  const std::vector<int> material(n, 1);
  std::vector<double> theta(2 * n, 0.0);
  for (std::size_t c = 0; c < n; ++c) theta[2 * c + 1] = 1.0;
  const std::vector<double> unread(2 * n, 0.0);
  const handoff::FdmEnd end{back.view(), pressure, material, 2, theta, unread, unread, {}};
  const handoff::ParticleSet particles = handoff::fdm_to_mpm(k.fluid, end);
  ASSERT_EQ(particles.size(), 4 * n);
  double volume = 0.0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    volume += particles.volume[p];
    const auto where = k.whole.locate(
        {particles.position[0][p], particles.position[1][p], particles.position[2][p]});
    ASSERT_TRUE(where.has_value());
    EXPECT_LT(where->cell[0], k.fluid_box.hi[0]) << "particle " << p;
  }
  EXPECT_NEAR(volume, static_cast<double>(n) * k.whole.cell_volume(), 1e-13 * volume);
  const ConservedError e = relative_error(
      wire_cell_conserved(wire.rho, wire.momentum, wire.energy, k.whole.cell_volume()),
      particle_conserved(particles.view()));
  RecordProperty("relative_error", e.summary().dump());
  EXPECT_LE(e.mass, kAudit);
  EXPECT_LE(e.momentum, kAudit);
  EXPECT_LE(e.energy, kAudit);
}

}  // namespace
}  // namespace mpfd::coupler
