// Whole-field transfers of protocol v1.2 through `mpm_solver serve`
// (proto/README.md §15): a chunked export is the ExportRegion reply bit for
// bit whatever the chunk budget, a particle import is InjectParticles of the
// same arrays (the next steps bitwise equal), particles outside the region's
// box are refused with nothing changed, the commit sets the clock, discard
// returns a count only, and the Mises gauge reads a uniaxial stress.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "cosim/serving/field_stream.hpp"
#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::mpm {
namespace {

using namespace testing;
using ::testing::AllOf;
using ::testing::HasSubstr;

const std::vector<const char*> kParticleQuantities = {
    "id", "position", "velocity", "mass", "volume", "internal_energy", "material", "stress"};

/// blast_text's CFDMP regions, "all" particles, and "inflow": the cells x in [0, 4)
/// (x < 0.25 m, empty at the start) that imports fill; "fluid"/"fsi" split x at 0.5 m.
std::vector<v1::Region> transfer_regions() {
  auto regions = cfdmp_regions();
  std::vector<const char*> all_quantities = kParticleQuantities;
  all_quantities.push_back("burn_fraction");
  auto add = [&](const char* name, long lo, long hi, const std::vector<const char*>& q) {
    regions.push_back(region(name, v1::REGION_KIND_PARTICLES, {lo, 0, 0}, {hi, 16, 1}));
    for (const char* quantity : q) regions.back().add_quantities(quantity);
  };
  add("all", 0, 16, all_quantities);
  add("inflow", 0, 4, kParticleQuantities);
  add("fluid", 0, 8, {"id"});
  add("fsi", 8, 16, {"id"});
  return regions;
}

cosim::Message export_region(ServedMpm& served, const std::string& name) {
  cosim::Message message;
  add_export(message, name);
  return served.request(std::move(message));
}

/// Streams `names` out of the zone with FieldExportRequest; returns the assembled
/// fields and checks every chunk against the budget (at least one row).
cosim::Message export_fields(ServedMpm& served, const std::vector<std::string>& names,
                             std::uint64_t max_chunk_bytes, std::uint32_t* chunks = nullptr) {
  cosim::Message request;
  auto& body = *request.header.mutable_field_export();
  body.set_transfer_id("export-1");
  for (const auto& name : names) body.add_fields(name);
  body.set_max_chunk_bytes(max_chunk_bytes);
  const std::uint64_t sequence = served.hub().send("mpm", std::move(request));
  cosim::FieldAssembly assembly("export-1");
  while (!assembly.complete()) {
    const cosim::Message chunk = served.hub().receive_from("mpm");
    EXPECT_EQ(chunk.header.envelope().in_reply_to(), sequence);
    const auto& array = chunk.header.arrays(0);
    const std::uint64_t rows = array.shape(0);
    const std::uint64_t bytes = chunk.frames.at(array.frame_index()).size();
    if (rows > 1) {
      EXPECT_LE(bytes, max_chunk_bytes) << chunk.header.field_chunk().field();
    }
    assembly.add(chunk);
  }
  if (chunks != nullptr) *chunks = assembly.chunks();
  return assembly.take();
}

/// Whether array group/name has the same dtype, shape and bytes in both messages.
::testing::AssertionResult same_array(const cosim::Message& a, const cosim::Message& b,
                                      const std::string& group, const std::string& name) {
  const auto& da = cosim::find_descriptor(a, group, name);
  const auto& db = cosim::find_descriptor(b, group, name);
  const auto& fa = a.frames.at(da.frame_index());
  const auto& fb = b.frames.at(db.frame_index());
  if (da.dtype() != db.dtype() ||
      !std::equal(da.shape().begin(), da.shape().end(), db.shape().begin(), db.shape().end()))
    return ::testing::AssertionFailure() << group << "/" << name << ": dtype or shape differ";
  if (fa.size() != fb.size() || (fa.size() > 0 && std::memcmp(fa.data(), fb.data(), fa.size())))
    return ::testing::AssertionFailure() << group << "/" << name << ": bytes differ";
  return ::testing::AssertionSuccess();
}

/// `count` particles of material 0 (gas) spread over x in [0.02, 0.23), moving
/// in +x, with a stress, as arrays of group `group`.
cosim::Message particle_batch(const std::string& group, std::size_t count) {
  std::vector<std::uint64_t> id(count);
  std::vector<double> position(3 * count), velocity(3 * count), mass(count), volume(count),
      energy(count), stress(6 * count, 0.0);
  std::vector<std::uint32_t> material(count, 0);
  for (std::size_t i = 0; i < count; ++i) {
    const double s = static_cast<double>(i) / static_cast<double>(count);
    id[i] = 1000 + i;
    position[3 * i] = 0.02 + 0.21 * s;
    position[3 * i + 1] = 0.05 + 0.9 * std::fmod(7.0 * s, 1.0);
    position[3 * i + 2] = 0.03125;
    velocity[3 * i] = 30.0 + 10.0 * s;
    velocity[3 * i + 1] = -5.0 * s;
    mass[i] = 1.0e-4 * (1.0 + s);
    volume[i] = mass[i] / 1.2;
    energy[i] = mass[i] * 2.5e5 / 1.2 * (1.0 + 0.1 * s);
    for (int c = 0; c < 3; ++c) stress[6 * i + c] = -1.0e5 * (1.0 + 0.1 * s);
  }
  cosim::Message message;
  cosim::add_array(message, {group, "id", {}, "1"}, std::move(id));
  cosim::add_array(message, {group, "position", {count, 3}, "m"}, std::move(position));
  cosim::add_array(message, {group, "velocity", {count, 3}, "m/s"}, std::move(velocity));
  cosim::add_array(message, {group, "mass", {}, "kg"}, std::move(mass));
  cosim::add_array(message, {group, "volume", {}, "m^3"}, std::move(volume));
  cosim::add_array(message, {group, "internal_energy", {}, "J"}, std::move(energy));
  cosim::add_array(message, {group, "material", {}, "1"}, std::move(material));
  cosim::add_array(message, {group, "stress", {count, 6}, "Pa"}, std::move(stress));
  return message;
}

std::vector<std::string> field_names(const std::string& region) {
  std::vector<std::string> names;
  for (const char* q : kParticleQuantities) names.push_back(region + "/" + q);
  return names;
}

/// Sends the fields of `batch` as FieldChunks (each acknowledged), then commits.
cosim::Message import_fields(ServedMpm& served, const cosim::Message& batch,
                             const std::string& transfer_id, std::uint64_t max_chunk_bytes) {
  const auto names = field_names("inflow");
  for (auto& chunk : cosim::slice_into_chunks(batch, transfer_id, names, max_chunk_bytes)) {
    const auto index = chunk.header.field_chunk().chunk_index();
    const auto ack = served.request(std::move(chunk));
    EXPECT_EQ(ack.header.field_chunk_ack().chunk_index(), index);
    EXPECT_EQ(ack.header.field_chunk_ack().transfer_id(), transfer_id);
  }
  cosim::Message commit;
  commit.header.mutable_field_import_commit()->set_transfer_id(transfer_id);
  return served.request(std::move(commit));
}

TEST(MpmServeFieldTransfer, FieldExportEqualsExportRegionBitForBitForChunkSizes) {
  ServedMpm served;
  double dt =
      served.request(setup(blast_text(), transfer_regions())).header.setup_ack().stable_dt();
  run_steps(served, dt, 0.0, 20);
  std::vector<std::string> names = {"ghost_nodes/internal_energy", "ghost_nodes/mass",
                                    "ghost_nodes/momentum"};
  for (const char* q : kParticleQuantities) names.push_back(std::string("all/") + q);
  names.push_back("all/burn_fraction");
  const auto particles = export_region(served, "all");
  const auto nodes = export_region(served, "ghost_nodes");
  const std::size_t n = particles.header.exchange_result().results(0).exported().count();
  ASSERT_GT(n, 100U);
  // 1 byte: one row per chunk; 1000: an odd budget (41 stress rows of 48 bytes); 64 MiB: whole.
  for (const std::uint64_t budget :
       {std::uint64_t{1}, std::uint64_t{1000}, std::uint64_t{64} << 20}) {
    std::uint32_t chunks = 0;
    const auto fields = export_fields(served, names, budget, &chunks);
    for (const auto& name : names) {
      const auto slash = name.find('/');
      const auto& reference = name.starts_with("all/") ? particles : nodes;
      EXPECT_TRUE(same_array(fields, reference, name.substr(0, slash), name.substr(slash + 1)))
          << "budget " << budget;
    }
    // ghost_nodes: 3 x 17 nodes, 2 x 16 cells; then 9 particle fields of n rows.
    if (budget == 1) {
      EXPECT_EQ(chunks, 2 * 51 + 32 + 9 * n);
    } else if (budget == std::uint64_t{64} << 20) {
      EXPECT_EQ(chunks, names.size());
    }
  }
}

TEST(MpmServeFieldTransfer, ParticleImportEqualsInjectParticlesAndTheNextStepsBitwise) {
  ServedMpm injected, imported;
  double dt_a =
      injected.request(setup(blast_text(), transfer_regions())).header.setup_ack().stable_dt();
  double dt_b =
      imported.request(setup(blast_text(), transfer_regions())).header.setup_ack().stable_dt();
  double time_a = run_steps(injected, dt_a, 0.0, 10);
  double time_b = run_steps(imported, dt_b, 0.0, 10);
  ASSERT_EQ(time_a, time_b);
  const std::size_t before =
      export_region(imported, "all").header.exchange_result().results(0).exported().count();

  cosim::Message inject = particle_batch("inflow", 40);
  add_op(inject).mutable_inject()->set_group("inflow");
  add_propose(inject);
  const auto inject_reply = injected.request(std::move(inject));
  dt_a = inject_reply.header.exchange_result().results(1).proposed().stable_dt();

  imported.hub().set_clock(10, time_b);
  const auto done = import_fields(imported, particle_batch("inflow", 40), "h2", 300);
  ASSERT_TRUE(done.header.has_field_import_done());
  EXPECT_EQ(done.header.field_import_done().transfer_id(), "h2");
  dt_b = done.header.field_import_done().stable_dt();
  EXPECT_EQ(dt_b, dt_a);

  // Totals of the added particles: the batch's own sums (energy E + m|v|^2/2), to round-off.
  const auto batch = particle_batch("inflow", 40);
  const auto m = array_of(batch, "inflow", "mass");
  const auto v = array_of(batch, "inflow", "velocity");
  const auto e = array_of(batch, "inflow", "internal_energy");
  std::array<double, 5> sums{};
  for (std::size_t p = 0; p < m.size(); ++p) {
    sums[0] += m[p];
    for (std::size_t a = 0; a < 3; ++a) sums[1 + a] += m[p] * v[3 * p + a];
    sums[4] += e[p] + 0.5 * m[p] * (v[3 * p] * v[3 * p] + v[3 * p + 1] * v[3 * p + 1]);
  }
  const auto& totals = done.header.field_import_done().totals();
  ASSERT_EQ(totals.size(), 5);
  EXPECT_NEAR(totals[0], sums[0], 1e-14 * sums[0]);
  EXPECT_NEAR(totals[1], sums[1], 1e-14 * sums[1]);
  EXPECT_NEAR(totals[2], sums[2], 1e-14 * std::abs(sums[1]));
  EXPECT_EQ(totals[3], 0.0);
  EXPECT_NEAR(totals[4], sums[4], 1e-14 * sums[4]);

  time_a = run_steps(injected, dt_a, time_a, 5);
  time_b = run_steps(imported, dt_b, time_b, 5);
  EXPECT_EQ(time_a, time_b);
  const auto a = export_region(injected, "all");
  const auto b = export_region(imported, "all");
  EXPECT_EQ(b.header.exchange_result().results(0).exported().count(), before + 40);
  for (const char* q : kParticleQuantities) EXPECT_TRUE(same_array(a, b, "all", q));
}

TEST(MpmServeFieldTransfer, AParticleOutsideItsRegionIsMalformedAndNothingChanges) {
  ServedMpm served;
  served.request(setup(blast_text(), transfer_regions()));
  const auto count = [&] {
    return export_region(served, "all").header.exchange_result().results(0).exported().count();
  };
  const std::size_t before = count();
  cosim::Message batch = particle_batch("inflow", 5);
  // Particle 3 at x = 0.3 m: inside the grid, outside inflow's x in [0, 0.25).
  const auto& array = cosim::find_descriptor(batch, "inflow", "position");
  static_cast<double*>(batch.frames.at(array.frame_index()).data())[9] = 0.3;
  const std::string refusal = [&] {
    try {
      import_fields(served, batch, "bad", 64);
    } catch (const Error& error) {
      return std::string(error.what());
    }
    return std::string("(committed)");
  }();
  EXPECT_THAT(refusal, AllOf(HasSubstr("MALFORMED"), HasSubstr("region 'inflow': particle 3"),
                             HasSubstr("id 1003"), HasSubstr("outside the region's box")));
  EXPECT_EQ(count(), before);  // and the zone still serves
  // A commit with nothing assembled is refused too, still not fatal.
  cosim::Message commit;
  commit.header.mutable_field_import_commit()->set_transfer_id("bad");
  EXPECT_THAT(served.refusal(std::move(commit)), HasSubstr("no import of transfer 'bad'"));
  EXPECT_EQ(count(), before);
}

TEST(MpmServeFieldTransfer, AChunkOfANewTransferDiscardsTheUnfinishedOne) {
  ServedMpm served;
  served.request(setup(blast_text(), transfer_regions()));
  auto first =
      cosim::slice_into_chunks(particle_batch("inflow", 5), "a", field_names("inflow"), 64);
  served.request(std::move(first.front()));  // transfer 'a' stops after one chunk
  import_fields(served, particle_batch("inflow", 5), "b", 64);
  cosim::Message commit;
  commit.header.mutable_field_import_commit()->set_transfer_id("a");
  EXPECT_THAT(served.refusal(std::move(commit)), HasSubstr("no import of transfer 'a'"));
  EXPECT_EQ(export_region(served, "inflow").header.exchange_result().results(0).exported().count(),
            5U);
}

TEST(MpmServeFieldTransfer, ImportsIntoNodesOrWithTracersOrOfUndeclaredQuantitiesAreRefused) {
  ServedMpm served;
  served.request(setup(blast_text(), transfer_regions()));
  const auto refusal_of = [&](const cosim::Message& fields, const std::vector<std::string>& names,
                              bool tracers) {
    for (auto& chunk : cosim::slice_into_chunks(fields, "t", names, 1 << 20))
      served.request(std::move(chunk));
    cosim::Message commit;
    commit.header.mutable_field_import_commit()->set_transfer_id("t");
    commit.header.mutable_field_import_commit()->set_tracers(tracers);
    return served.refusal(std::move(commit));
  };
  EXPECT_THAT(refusal_of(particle_batch("inflow", 2), field_names("inflow"), true),
              HasSubstr("no TRACERS regions"));
  cosim::Message nodes;
  cosim::add_array(nodes, {"ghost_nodes", "mass", {}, "kg"}, std::vector<double>(51, 1.0));
  EXPECT_THAT(refusal_of(nodes, {"ghost_nodes/mass"}, false),
              AllOf(HasSubstr("UNEXPECTED"), HasSubstr("NODES regions export only")));
  cosim::Message fluid = particle_batch("fluid", 2);  // "fluid" declares only id
  EXPECT_THAT(refusal_of(fluid, field_names("fluid"), false),
              AllOf(HasSubstr("UNKNOWN_REGION"), HasSubstr("'fluid/position'")));
  cosim::Message partial = particle_batch("inflow", 2);
  EXPECT_THAT(refusal_of(partial, {"inflow/id", "inflow/mass"}, false),
              HasSubstr("array 'position' is missing"));
  EXPECT_EQ(export_region(served, "all").header.exchange_result().results(0).exported().count(),
            512U);  // the scene's particles, nothing added
}

TEST(MpmServeFieldTransfer, CommitSetsTheClockToItsSimTime) {
  ServedMpm served;
  served.request(setup(blast_text(), transfer_regions()));
  served.hub().set_clock(0, 0.5);
  const double dt = import_fields(served, particle_batch("inflow", 3), "t", 1 << 20)
                        .header.field_import_done()
                        .stable_dt();
  cosim::Message exchange;
  add_advance(exchange, dt, 0.5);
  const auto reply = served.request(std::move(exchange));
  EXPECT_DOUBLE_EQ(reply.header.exchange_result().results(0).advanced().time(), 0.5 + dt);
}

TEST(MpmServeFieldTransfer, RemoveDiscardReturnsTheCountOnly) {
  ServedMpm served;
  double dt =
      served.request(setup(blast_text(), transfer_regions())).header.setup_ack().stable_dt();
  run_steps(served, dt, 0.0, 40);
  const auto all = export_region(served, "all");
  const auto x = array_of(all, "all", "position");
  std::uint64_t outside = 0;  // mpm_zone: cells x in [4, 12), x in [0.25, 0.75)
  for (std::size_t p = 0; p < x.size() / 3; ++p) outside += x[3 * p] < 0.25 || x[3 * p] >= 0.75;
  ASSERT_GT(outside, 0U);
  cosim::Message remove;
  auto& op = *add_op(remove).mutable_remove();
  op.set_group("to_fdm");
  op.set_left_region("mpm_zone");
  op.set_discard(true);
  const auto reply = served.request(std::move(remove));
  EXPECT_EQ(reply.header.exchange_result().results(0).removed().removed(), outside);
  EXPECT_EQ(reply.header.arrays_size(), 0);
  EXPECT_EQ(export_region(served, "all").header.exchange_result().results(0).exported().count(),
            x.size() / 3 - outside);
}

TEST(MpmServeFieldTransfer, FluidAndFsiParticleRegionsPartitionTheZone) {
  ServedMpm served;
  double dt =
      served.request(setup(blast_text(), transfer_regions())).header.setup_ack().stable_dt();
  run_steps(served, dt, 0.0, 20);
  const auto fields = export_fields(served, {"fluid/id", "fsi/id"}, 1000);
  auto fluid = array_of<std::uint64_t>(fields, "fluid", "id");
  auto fsi = array_of<std::uint64_t>(fields, "fsi", "id");
  auto all = array_of<std::uint64_t>(export_region(served, "all"), "all", "id");
  ASSERT_FALSE(fluid.empty());
  ASSERT_FALSE(fsi.empty());
  std::vector<std::uint64_t> both = fluid;
  both.insert(both.end(), fsi.begin(), fsi.end());
  std::sort(both.begin(), both.end());
  std::sort(all.begin(), all.end());
  EXPECT_EQ(both, all);  // every particle once: no overlap, no gap
}

TEST(MpmServeFieldTransfer, MisesGaugeOfAUniaxialStressIsItsMagnitude) {
  ServedMpm served;
  served.request(setup(blast_text(), transfer_regions()));
  cosim::Message inject = particle_batch("inflow", 1);
  const double sigma = -3.0e7;  // uniaxial compression along x
  const auto& array = cosim::find_descriptor(inject, "inflow", "stress");
  double* stress = static_cast<double*>(inject.frames.at(array.frame_index()).data());
  std::fill(stress, stress + 6, 0.0);
  stress[0] = sigma;
  add_op(inject).mutable_inject()->set_group("inflow");
  auto& sample = *add_op(inject).mutable_sample();
  sample.set_group("gauges");
  sample.add_gauge_names("probe");
  for (const double x : {0.02, 0.05, 0.03125}) sample.add_positions(x);  // the particle's place
  for (const char* q : {"mises_stress", "pressure"}) sample.add_quantities(q);
  const auto reply = served.request(std::move(inject));
  // s = sigma - tr(sigma)/3 I = sigma (2/3, -1/3, -1/3): sqrt(3/2 s:s) = |sigma|.
  EXPECT_NEAR(array_of(reply, "gauges", "mises_stress")[0], std::abs(sigma), 1e-12 * 3.0e7);
  EXPECT_NEAR(array_of(reply, "gauges", "pressure")[0], -sigma / 3.0, 1e-12 * 3.0e7);
}

}  // namespace
}  // namespace mpfd::mpm
