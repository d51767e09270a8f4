// Particle transport through `mpm_solver serve` (T §4.3 step 14): removal
// returns exactly what leaves the zone, injection adds exactly what it is
// given (mass, momentum, energy), ids round-trip, and a nodal force applied
// to the interface nodes changes the momentum by sum F dt ((4-7)...(4-9)).

#include <gtest/gtest.h>

#include <cmath>

#include "common/config/scene_loader.hpp"
#include "mpm_solver/mpm_solver.hpp"
#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::mpm {
namespace {

using namespace testing;

struct Totals {
  double mass = 0.0;
  std::array<double, 3> momentum{};
  double energy = 0.0;  ///< kinetic + internal [J]
  std::size_t count = 0;
};

/// Totals of arrays group/{mass, velocity, internal_energy} in `message`.
Totals totals_of(const cosim::Message& message, const std::string& group) {
  const auto mass = array_of(message, group, "mass");
  const auto velocity = array_of(message, group, "velocity");
  const auto energy = array_of(message, group, "internal_energy");
  Totals t;
  t.count = mass.size();
  for (std::size_t p = 0; p < mass.size(); ++p) {
    t.mass += mass[p];
    double v2 = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
      t.momentum[a] += mass[p] * velocity[3 * p + a];
      v2 += velocity[3 * p + a] * velocity[3 * p + a];
    }
    t.energy += 0.5 * mass[p] * v2 + energy[p];
  }
  return t;
}

cosim::Message export_all() {
  cosim::Message message;
  add_export(message, "all");
  return message;
}

/// Copies every array of group `from` in `source` into `target` as group `to`.
void copy_group(const cosim::Message& source, const std::string& from, cosim::Message& target,
                const std::string& to) {
  for (const auto& array : source.header.arrays()) {
    if (array.group() != from) continue;
    const auto& frame = source.frames.at(array.frame_index());
    zmq::message_t copy(frame.data(), frame.size());
    std::vector<std::uint64_t> shape(array.shape().begin(), array.shape().end());
    std::uint64_t count = 1;
    for (const auto n : shape) count *= n;
    cosim::append_frame(target, {to, array.name(), shape, array.units()}, array.dtype(),
                        static_cast<std::size_t>(count), std::move(copy));
  }
}

TEST(MpmServeParticles, RemovalReturnsWhatLeftAndReinjectionRestoresMassMomentumEnergy) {
  ServedMpm served;
  double dt =
      served.request(setup(blast_text(), regions_with_all())).header.setup_ack().stable_dt();
  const double time = run_steps(served, dt, 0.0, 40);
  const Totals before = totals_of(served.request(export_all()), "all");

  cosim::Message remove;
  auto& op = *add_op(remove).mutable_remove();
  op.set_group("crossed");
  op.set_left_region("mpm_zone");
  add_export(remove, "all");
  const auto removed_reply = served.request(std::move(remove));
  const Totals removed = totals_of(removed_reply, "crossed");
  const Totals after = totals_of(removed_reply, "all");
  ASSERT_GT(removed.count, 0U);  // the blast pushed particles out of x in [0.25, 0.75)
  EXPECT_EQ(removed_reply.header.exchange_result().results(0).removed().removed(), removed.count);
  EXPECT_EQ(after.count + removed.count, before.count);
  // Round-off of summing in another order: 1e-14 relative.
  EXPECT_NEAR(after.mass + removed.mass, before.mass, 1e-14 * before.mass);
  EXPECT_NEAR(after.energy + removed.energy, before.energy, 1e-14 * before.energy);
  const double p_scale = std::sqrt(2.0 * before.mass * before.energy);
  for (std::size_t a = 0; a < 3; ++a)
    EXPECT_NEAR(after.momentum[a] + removed.momentum[a], before.momentum[a], 1e-14 * p_scale);
  for (const double x : array_of(removed_reply, "crossed", "position"))
    EXPECT_TRUE(std::isfinite(x));
  const auto positions = array_of(removed_reply, "crossed", "position");
  for (std::size_t p = 0; p < removed.count; ++p) {
    const double x = positions[3 * p];
    EXPECT_TRUE(x < 0.25 || x >= 0.75) << "removed particle " << p << " at x = " << x;
  }

  // Inject them back (the coupler's ids, stress given): the totals return.
  cosim::Message inject;
  add_op(inject).mutable_inject()->set_group("injected");
  copy_group(removed_reply, "crossed", inject, "injected");
  add_export(inject, "all");
  const auto injected_reply = served.request(std::move(inject));
  EXPECT_EQ(injected_reply.header.exchange_result().results(0).injected().injected(),
            removed.count);
  const Totals back = totals_of(injected_reply, "all");
  EXPECT_EQ(back.count, before.count);
  EXPECT_NEAR(back.mass, before.mass, 1e-14 * before.mass);
  EXPECT_NEAR(back.energy, before.energy, 1e-14 * before.energy);
  for (std::size_t a = 0; a < 3; ++a)
    EXPECT_NEAR(back.momentum[a], before.momentum[a], 1e-14 * p_scale);
  // The stress given is the stress held: p = -tr/3 and the deviator round-trip.
  const auto stress_out = array_of(removed_reply, "crossed", "stress");
  const auto stress_back = array_of(injected_reply, "all", "stress");
  const std::size_t first = 6 * after.count;  // injected particles come last
  for (std::size_t i = 0; i < stress_out.size(); ++i)
    EXPECT_NEAR(stress_back[first + i], stress_out[i], 1e-9 * std::abs(stress_out[i]) + 1e-9);

  // Removal by id takes exactly the listed particles.
  const auto ids = array_of<std::uint64_t>(injected_reply, "all", "id");
  cosim::Message by_id;
  add_op(by_id).mutable_remove()->set_group("gone");
  const std::vector<std::uint64_t> two = {ids[3], ids.back()};
  cosim::add_array(by_id, {"gone", "id", {}, "1"}, std::span<const std::uint64_t>(two));
  const auto gone = served.request(std::move(by_id));
  EXPECT_EQ(array_of<std::uint64_t>(gone, "gone", "id"), two);
  // The zone goes on stepping with the injected particles.
  run_steps(served, dt, time, 5);
}

TEST(MpmServeParticles, OutflowExportIsTheLedgerAndClosesTheMassAudit) {
  // v1.1 boundary_outflow: particles the blast drives through the outflow x
  // faces are in outflow_*, so what is inside plus what left stays the start.
  auto regions = cfdmp_regions();
  regions.push_back(region("all", v1::REGION_KIND_PARTICLES, {0, 0, 0}, {16, 16, 1},
                           {"mass", "velocity", "internal_energy", "outflow_mass",
                            "outflow_momentum", "outflow_energy"}));
  ServedMpm served;
  double dt = served.request(setup(blast_text(), regions)).header.setup_ack().stable_dt();
  const auto start_reply = served.request(export_all());
  const Totals start = totals_of(start_reply, "all");
  EXPECT_EQ(array_of(start_reply, "all", "outflow_mass"), std::vector<double>{0.0});
  const auto scene = config::parse_scene(blast_text(), "blast.yaml");
  MpmSolver direct(scene, MpmSettings::from_scene(scene));
  double time = 0.0;
  for (int s = 0; s < 150; ++s) {
    cosim::Message exchange;
    add_advance(exchange, dt, time);
    served.request(std::move(exchange));
    direct.advance(dt);
    time += dt;
    dt = direct.stable_dt();
  }
  const auto reply = served.request(export_all());
  const Totals inside = totals_of(reply, "all");
  const auto out_mass = array_of(reply, "all", "outflow_mass");
  const auto out_momentum = array_of(reply, "all", "outflow_momentum");
  ASSERT_EQ(out_mass.size(), 1U);
  ASSERT_EQ(out_momentum.size(), 3U);
  const BoundaryLedger& ledger = direct.boundary_ledger();
  EXPECT_GT(ledger.particles_removed, 0);  // the test exercises the outflow faces
  EXPECT_EQ(out_mass[0], ledger.mass);
  EXPECT_EQ(out_momentum[0], ledger.momentum[0]);
  EXPECT_EQ(array_of(reply, "all", "outflow_energy").at(0), ledger.energy);
  EXPECT_NEAR(inside.mass + out_mass[0], start.mass, 1e-14 * start.mass);
}

TEST(MpmServeParticles, AForceOnTheInterfaceNodesAddsSumFDtToTheMomentum) {
  ServedMpm served;
  const double dt =
      served.request(setup(blast_text(), regions_with_all())).header.setup_ack().stable_dt();
  const auto scene = config::parse_scene(blast_text(), "blast.yaml");
  MpmSolver direct(scene, MpmSettings::from_scene(scene));
  direct.advance(dt);

  // N per node along x, on nodes j = 1..15: the y walls fix every component on j = 0, 16.
  constexpr double force = 250.0;
  cosim::Message step;
  auto& apply = *add_op(step).mutable_apply();
  apply.set_region("interface_nodes");
  apply.set_mode(v1::ApplyRegion::MODE_ADD);
  std::vector<double> f(17 * 3, 0.0);
  for (std::size_t n = 1; n < 16; ++n) f[3 * n] = force;
  cosim::add_array(step, {"interface_nodes", "internal_force", {17, 3}, "N"},
                   std::span<const double>(f));
  add_advance(step, dt, 0.0);
  add_export(step, "all");
  const Totals served_totals = totals_of(served.request(std::move(step)), "all");
  double direct_px = 0.0;
  for (std::size_t p = 0; p < direct.particles().size(); ++p)
    direct_px += direct.particles().mass[p] * direct.particles().velocity[0][p];
  // Every interface node carries particle mass, so (2-15) hands all of F dt on.
  EXPECT_NEAR(served_totals.momentum[0] - direct_px, 15 * force * dt, 1e-9 * 15 * force * dt);
}

// T (4-3) with the support of (4-1): e_c is the nodal sum_p N_Ip m_p e_p at the cell
// centre, so e_c / m_c is the particles' e in every ghost cell. Regression: summing
// only the particles inside the cell gave e_c = 0 to cell x = 3, which holds none
// while its corner nodes x = 4 carry mass: the FDM got p = 0 there (the 2D blast
// stopped with "unphysical state" in a ghost cell next to its wall).
TEST(MpmServeParticles, GhostNodesExportTheInternalEnergyWithTheSupportOfTheNodalMass) {
  ServedMpm served;
  served.request(setup(blast_text(), cfdmp_regions()));
  cosim::Message exchange;
  add_export(exchange, "ghost_nodes");
  const auto reply = served.request(std::move(exchange));
  const auto energy = array_of(reply, "ghost_nodes", "internal_energy");
  const auto mass = array_of(reply, "ghost_nodes", "mass");
  // Nodes x 3..5, y 0..16 (C order, y fastest) bound cells x 3 and 4, y 0..15: 32 cells.
  ASSERT_EQ(mass.size(), 3U * 17U);
  ASSERT_EQ(energy.size(), 32U);
  // The gas (x >= 0.25, node 4) holds 1 kg/m^3 at e = p / ((gamma - 1) rho) = 2.5e5 J/kg.
  const double e = 2.5e5;
  const auto node = [&](std::size_t i, std::size_t j) { return mass[i * 17 + j]; };
  for (std::size_t i = 0; i < 2; ++i)
    for (std::size_t j = 0; j < 16; ++j) {
      const double m_c =
          0.25 * (node(i, j) + node(i, j + 1) + node(i + 1, j) + node(i + 1, j + 1));  // (4-1)
      ASSERT_GT(m_c, 0.0) << "cell (" << 3 + i << ", " << j << ")";
      EXPECT_NEAR(energy[i * 16 + j], e * m_c, 1e-12 * e * m_c)
          << "cell (" << 3 + i << ", " << j << ")";
    }
}

TEST(MpmServeParticles, ANodeLoadNoParticleReachesLeavesTheStepBitForBit) {
  ServedMpm served;
  auto regions = cfdmp_regions();
  regions.push_back(region("left_face", v1::REGION_KIND_NODES, {0, 0, 0}, {1, 17, 1},
                           {"mass", "momentum", "internal_force"}));
  regions.push_back(
      region("all", v1::REGION_KIND_PARTICLES, {0, 0, 0}, {16, 16, 1}, {"position", "velocity"}));
  const double dt = served.request(setup(blast_text(), regions)).header.setup_ack().stable_dt();
  const auto scene = config::parse_scene(blast_text(), "blast.yaml");
  MpmSolver direct(scene, MpmSettings::from_scene(scene));
  direct.advance(dt);

  cosim::Message step;
  for (const auto mode : {v1::ApplyRegion::MODE_SET, v1::ApplyRegion::MODE_ADD}) {
    auto& apply = *add_op(step).mutable_apply();
    apply.set_region("left_face");
    apply.set_mode(mode);
  }
  const std::vector<double> mass(17, 1.0), vector(17 * 3, 5.0);
  cosim::add_array(step, {"left_face", "mass", {}, "kg"}, std::span<const double>(mass));
  cosim::add_array(step, {"left_face", "momentum", {17, 3}, "kg*m/s"},
                   std::span<const double>(vector));
  cosim::add_array(step, {"left_face", "internal_force", {17, 3}, "N"},
                   std::span<const double>(vector));
  add_advance(step, dt, 0.0);
  add_export(step, "all");
  const auto reply = served.request(std::move(step));
  // Nodes x = 0 are two cells from the gas (x >= 0.25): their blocks are made for the
  // loads, and no particle reads them.
  const auto position = array_of(reply, "all", "position");
  const auto velocity = array_of(reply, "all", "velocity");
  const ParticleSet& ps = direct.particles();
  ASSERT_EQ(position.size(), 3 * ps.size());
  for (std::size_t p = 0; p < ps.size(); ++p)
    for (std::size_t a = 0; a < 3; ++a) {
      ASSERT_EQ(position[3 * p + a], ps.position[a][p]);
      ASSERT_EQ(velocity[3 * p + a], ps.velocity[a][p]);
    }
}

}  // namespace
}  // namespace mpfd::mpm
