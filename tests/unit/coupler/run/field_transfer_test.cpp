// The coupler's whole-field transfers (coupler/run/field_transfer.hpp, proto
// README §15) against the real `mpm_solver serve` and `fdm_solver serve` on a
// thread: the chunk budget changes the number of chunks, never the arrays; an
// import's FieldImportDone totals are the coupler's own sums of what it sent;
// a refusal names the solver and the field.

#include "coupler/run/field_transfer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "tests/unit/fdm_solver/serve/serve_harness.hpp"
#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::coupler {
namespace {

using mpm::testing::ServedMpm;
namespace v1 = cosim::v1;
using ::testing::AllOf;
using ::testing::HasSubstr;

/// A deep copy: import_fields consumes the message it sends.
cosim::Message copy_of(const cosim::Message& message) {
  cosim::Message copy;
  copy.header = message.header;
  for (const auto& frame : message.frames) copy.frames.emplace_back(frame.data(), frame.size());
  return copy;
}

constexpr std::chrono::milliseconds kTimeout{10000};

const std::vector<std::string> kQuantities = {"id",     "position",        "velocity", "mass",
                                              "volume", "internal_energy", "material", "stress"};

std::vector<std::string> names_of(const std::string& region, bool with_burn_fraction) {
  std::vector<std::string> names;
  for (const auto& q : kQuantities) names.push_back(region + "/" + q);
  if (with_burn_fraction) names.push_back(region + "/burn_fraction");
  return names;
}

/// The blast zone of serve_harness with AFDMP's particle regions: fluid_particles
/// (cells x in [0, 8)) and inflow (x in [0, 4), empty at the start).
double set_up(ServedMpm& served) {
  auto particle_region = [](const char* name, long hi, bool burn) {
    v1::Region r = mpm::testing::region(name, v1::REGION_KIND_PARTICLES, {0, 0, 0}, {hi, 16, 1});
    for (const auto& q : kQuantities) r.add_quantities(q);
    if (burn) r.add_quantities("burn_fraction");
    return r;
  };
  return served
      .request(mpm::testing::setup(
          mpm::testing::blast_text(),
          {particle_region("fluid_particles", 8, true), particle_region("inflow", 4, false)}))
      .header.setup_ack()
      .stable_dt();
}

void run_steps(ServedMpm& served, double dt, int steps) {
  double time = 0.0;
  for (int s = 0; s < steps; ++s) {
    cosim::Message exchange;
    mpm::testing::add_advance(exchange, dt, time);
    mpm::testing::add_propose(exchange);
    const auto reply = served.request(std::move(exchange));
    time = reply.header.exchange_result().results(0).advanced().time();
    dt = reply.header.exchange_result().results(1).proposed().stable_dt();
  }
}

bool same_bytes(const cosim::Message& a, const cosim::Message& b, const std::string& field) {
  const auto slash = field.find('/');
  const auto& da = cosim::find_descriptor(a, field.substr(0, slash), field.substr(slash + 1));
  const auto& db = cosim::find_descriptor(b, field.substr(0, slash), field.substr(slash + 1));
  const auto& fa = a.frames.at(da.frame_index());
  const auto& fb = b.frames.at(db.frame_index());
  return da.dtype() == db.dtype() &&
         std::equal(da.shape().begin(), da.shape().end(), db.shape().begin(), db.shape().end()) &&
         fa.size() == fb.size() &&
         (fa.size() == 0 || std::memcmp(fa.data(), fb.data(), fa.size()) == 0);
}

TEST(FieldTransfer, ExportOfFluidParticlesIsTheSameFor4KiBAnd64MiBChunks) {
  ServedMpm served;
  run_steps(served, set_up(served), 20);
  const auto names = names_of("fluid_particles", true);
  FieldTransferStats small, large;
  const auto a = export_fields(served.hub(), "mpm", "h1-small", names, 4096, kTimeout, &small);
  const auto b = export_fields(served.hub(), "mpm", "h1-large", names, std::uint64_t{64} << 20,
                               kTimeout, &large);
  const auto n = cosim::find_descriptor(a, "fluid_particles", "mass").shape(0);
  ASSERT_GT(n, 200U);  // stress alone: n x 48 bytes > 2 chunks of 4 KiB
  for (const auto& name : names) EXPECT_TRUE(same_bytes(a, b, name)) << name;
  // 8 + 24 + 24 + 8 + 8 + 8 + 4 + 48 + 8 bytes per particle: 140 n in all.
  EXPECT_EQ(small.bytes, 140 * n);
  EXPECT_EQ(large.bytes, 140 * n);
  EXPECT_EQ(large.chunks, names.size());
  std::uint32_t expected = 0;  // ceil(rows / rows per chunk) per field
  for (const std::uint64_t row : {8, 24, 24, 8, 8, 8, 4, 48, 8}) {
    const std::uint64_t rows_per_chunk = 4096 / row;
    expected += static_cast<std::uint32_t>((n + rows_per_chunk - 1) / rows_per_chunk);
  }
  EXPECT_EQ(small.chunks, expected);
}

TEST(FieldTransfer, ImportDoneTotalsEqualTheCouplersSumsOfWhatItSent) {
  ServedMpm served;
  set_up(served);
  const std::size_t n = 300;
  std::vector<std::uint64_t> id(n);
  std::vector<double> position(3 * n), velocity(3 * n), mass(n), volume(n), energy(n),
      stress(6 * n, 0.0);
  std::vector<std::uint32_t> material(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const double s = (static_cast<double>(i) + 0.5) / static_cast<double>(n);
    id[i] = (std::uint64_t{1} << 49) + i;
    position[3 * i] = 0.24 * s;
    position[3 * i + 1] = std::fmod(13.0 * s, 1.0);
    position[3 * i + 2] = 0.03;
    velocity[3 * i] = 340.0 * std::sin(7.0 * s);
    velocity[3 * i + 1] = -120.0 * s;
    velocity[3 * i + 2] = 0.0;
    mass[i] = 2.0e-4 * (1.0 + s * s);
    volume[i] = mass[i] / 1.3;
    energy[i] = mass[i] * 2.6e5 * (1.0 + s);
    for (int c = 0; c < 3; ++c) stress[6 * i + c] = -1.1e5;
  }
  std::array<double, 5> sums{};
  for (std::size_t i = 0; i < n; ++i) {
    sums[0] += mass[i];
    double v2 = 0.0;
    for (std::size_t a = 0; a < 3; ++a) {
      sums[1 + a] += mass[i] * velocity[3 * i + a];
      v2 += velocity[3 * i + a] * velocity[3 * i + a];
    }
    sums[4] += energy[i] + 0.5 * mass[i] * v2;
  }
  cosim::Message fields;
  cosim::add_array(fields, {"inflow", "id", {}, "1"}, std::move(id));
  cosim::add_array(fields, {"inflow", "position", {n, 3}, "m"}, std::move(position));
  cosim::add_array(fields, {"inflow", "velocity", {n, 3}, "m/s"}, std::move(velocity));
  cosim::add_array(fields, {"inflow", "mass", {}, "kg"}, std::move(mass));
  cosim::add_array(fields, {"inflow", "volume", {}, "m^3"}, std::move(volume));
  cosim::add_array(fields, {"inflow", "internal_energy", {}, "J"}, std::move(energy));
  cosim::add_array(fields, {"inflow", "material", {}, "1"}, std::move(material));
  cosim::add_array(fields, {"inflow", "stress", {n, 6}, "Pa"}, std::move(stress));

  FieldTransferStats stats;
  served.hub().set_clock(0, 1.0e-3);
  const auto names = names_of("inflow", false);
  const v1::FieldImportDone done = import_fields(served.hub(), "mpm", "h2", copy_of(fields), names,
                                                 4096, false, kTimeout, &stats);
  EXPECT_EQ(stats.bytes, 132 * n);  // 140 bytes a particle without burn_fraction
  EXPECT_GT(stats.seconds, 0.0);
  EXPECT_GT(stats.chunks, names.size());
  EXPECT_GT(done.stable_dt(), 0.0);
  ASSERT_EQ(done.totals_size(), 5);
  EXPECT_NEAR(done.totals(0), sums[0], 1e-14 * sums[0]);
  // Momentum against the scale sqrt(2 M E) (x sums terms of both signs).
  const double p_scale = std::sqrt(2.0 * sums[0] * sums[4]);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(done.totals(1 + a), sums[1 + a], 1e-14 * p_scale);
  EXPECT_NEAR(done.totals(4), sums[4], 1e-14 * sums[4]);
  // The particles are in the zone: the inflow region exports them back.
  const auto back = export_fields(served.hub(), "mpm", "check",
                                  std::vector<std::string>{"inflow/id"}, 0, kTimeout);
  EXPECT_EQ(cosim::find_descriptor(back, "inflow", "id").shape(0), n);

  // The same batch again, one particle moved out of the inflow box: refused, nothing added.
  const auto& x = cosim::find_descriptor(fields, "inflow", "position");
  static_cast<double*>(fields.frames.at(x.frame_index()).data())[3 * 17] = 0.6;
  try {
    (void)import_fields(served.hub(), "mpm", "h2-again", copy_of(fields), names, 4096, false,
                        kTimeout);
    ADD_FAILURE() << "a particle outside its region was imported";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), AllOf(HasSubstr("import"), HasSubstr("solver 'mpm'"),
                                    HasSubstr("transfer 'h2-again'"), HasSubstr("particle 17"),
                                    HasSubstr("outside the region's box")));
  }
  const auto after = export_fields(served.hub(), "mpm", "check-again",
                                   std::vector<std::string>{"inflow/id"}, 0, kTimeout);
  EXPECT_EQ(cosim::find_descriptor(after, "inflow", "id").shape(0), n);
}

TEST(FieldTransfer, ARefusalNamesTheSolverAndTheField) {
  ServedMpm served;
  set_up(served);
  const std::vector<std::string> names = {"fluid_particles/mass", "fluid_particles/rho"};
  try {
    (void)export_fields(served.hub(), "mpm", "bad", names, 4096, kTimeout);
    FAIL() << "the export of an undeclared quantity was answered";
  } catch (const Error& error) {
    EXPECT_THAT(error.what(), AllOf(HasSubstr("solver 'mpm'"), HasSubstr("transfer 'bad'"),
                                    HasSubstr("quantity 'rho'")));
  }
  // The refusal was not fatal: the next export goes through.
  const auto fields = export_fields(served.hub(), "mpm", "good", names_of("fluid_particles", false),
                                    4096, kTimeout);
  EXPECT_GT(cosim::find_descriptor(fields, "fluid_particles", "mass").shape(0), 0U);
}

TEST(FieldTransfer, FdmCellsExportedAndImportedBackKeepTheStateAndTotals) {
  fdm::testing::ServedFdm fdm;
  constexpr int n = 64;  // Sod's tube, cells of 1/64 m^3
  const auto all_cells =
      fdm::testing::cell_box("all_cells", {0, 0, 0}, {n, 1, 1}, {"rho", "momentum", "E"});
  double dt = fdm.request(fdm::testing::setup(fdm::testing::sod_text(n), {all_cells}))
                  .header.setup_ack()
                  .stable_dt();
  double time = 0.0;
  for (int step = 0; step < 20; ++step) {
    cosim::Message exchange;
    fdm::testing::add_advance(exchange, dt, time);
    exchange.header.mutable_exchange()->add_operations()->mutable_propose_dt();
    const auto reply = fdm.request(std::move(exchange));
    time = reply.header.exchange_result().results(0).advanced().time();
    dt = reply.header.exchange_result().results(1).proposed().stable_dt();
  }
  const std::vector<std::string> names = {"all_cells/rho", "all_cells/momentum", "all_cells/E"};
  FieldTransferStats small, large;
  const auto a = export_fields(fdm.hub(), "fdm", "cells-small", names, 100, kTimeout, &small);
  const auto b = export_fields(fdm.hub(), "fdm", "cells-large", names, 64 << 20, kTimeout, &large);
  for (const auto& name : names) EXPECT_TRUE(same_bytes(a, b, name)) << name;
  EXPECT_EQ(large.chunks, 3U);
  EXPECT_EQ(small.chunks, 6 + 16 + 6);  // 12 rows of 8 bytes, 4 rows of 24, 12 rows of 8
  EXPECT_EQ(small.bytes, 40U * n);

  std::array<double, 5> sums{};  // mass, momentum, E of the cells, V = 1/64 m^3
  const double volume = 1.0 / n;
  const auto rho = cosim::view_array<double>(a, "all_cells", "rho").values();
  const auto momentum = cosim::view_array<double>(a, "all_cells", "momentum").values();
  const auto energy = cosim::view_array<double>(a, "all_cells", "E").values();
  for (int c = 0; c < n; ++c) {
    sums[0] += rho[c] * volume;
    for (int k = 0; k < 3; ++k) sums[1 + k] += momentum[3 * c + k] * volume;
    sums[4] += energy[c] * volume;
  }
  fdm.hub().set_clock(20, time);
  const auto done =
      import_fields(fdm.hub(), "fdm", "cells-back", copy_of(a), names, 256, false, kTimeout);
  ASSERT_EQ(done.totals_size(), 5);
  EXPECT_NEAR(done.totals(0), sums[0], 1e-14 * sums[0]);
  EXPECT_NEAR(done.totals(1), sums[1], 1e-14 * std::sqrt(2.0 * sums[0] * sums[4]));
  EXPECT_NEAR(done.totals(4), sums[4], 1e-14 * sums[4]);
  const auto c = export_fields(fdm.hub(), "fdm", "cells-again", names, 0, kTimeout);
  for (const auto& name : names) EXPECT_TRUE(same_bytes(a, c, name)) << name;  // SET, bitwise
}

}  // namespace
}  // namespace mpfd::coupler
