// Checkpoint and Restore of `mpm_solver serve`: a zone restored from a
// checkpoint (injected particles included) continues bit for bit as the one
// that wrote it; a checkpoint whose bytes no longer match its .sha256 is
// refused and the running state stays as it was; a Restore that fails after
// it replaced the particles stops the solver, which holds a mixture.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "tests/unit/mpm_solver/serve/serve_harness.hpp"

namespace mpfd::mpm {
namespace {

using namespace testing;
using ::testing::HasSubstr;

struct Clock {
  double time = 0.0;
  double dt = 0.0;
};

void run(ServedMpm& served, Clock& clock, int steps) {
  for (int s = 0; s < steps; ++s) {
    cosim::Message exchange;
    add_advance(exchange, clock.dt, clock.time);
    add_propose(exchange);
    const auto reply = served.request(std::move(exchange));
    clock.time = reply.header.exchange_result().results(0).advanced().time();
    clock.dt = reply.header.exchange_result().results(1).proposed().stable_dt();
  }
}

/// As run, with the ghost_nodes export of a coupled step after each advance:
/// the solver maps the next step for it (MpmSolver::map_next_step).
void run_exporting_ghost_nodes(ServedMpm& served, Clock& clock, int steps) {
  for (int s = 0; s < steps; ++s) {
    cosim::Message exchange;
    add_advance(exchange, clock.dt, clock.time);
    add_export(exchange, "ghost_nodes");
    add_propose(exchange);
    const auto reply = served.request(std::move(exchange));
    clock.time = reply.header.exchange_result().results(0).advanced().time();
    clock.dt = reply.header.exchange_result().results(2).proposed().stable_dt();
  }
}

/// Gas particles of the coupler's, material 0, as InjectParticles arrays.
struct Injection {
  std::vector<std::uint64_t> id;
  std::vector<double> position, velocity, mass, volume, energy;  // [n, 3] for the vectors
};

void inject(ServedMpm& served, const Injection& in) {
  const std::size_t n = in.id.size();
  const std::vector<std::uint32_t> material(n, 0);
  cosim::Message exchange;
  add_op(exchange).mutable_inject()->set_group("injected");
  cosim::add_array(exchange, {"injected", "id", {}, "1"}, std::span<const std::uint64_t>(in.id));
  cosim::add_array(exchange, {"injected", "position", {n, 3}, "m"},
                   std::span<const double>(in.position));
  cosim::add_array(exchange, {"injected", "velocity", {n, 3}, "m/s"},
                   std::span<const double>(in.velocity));
  cosim::add_array(exchange, {"injected", "mass", {}, "kg"}, std::span<const double>(in.mass));
  cosim::add_array(exchange, {"injected", "volume", {}, "m^3"}, std::span<const double>(in.volume));
  cosim::add_array(exchange, {"injected", "internal_energy", {}, "J"},
                   std::span<const double>(in.energy));
  cosim::add_array(exchange, {"injected", "material", {}, "1"},
                   std::span<const std::uint32_t>(material));
  served.request(std::move(exchange));
}

/// Injects one particle of the coupler's (id 9000001) in the gas at x = 0.5.
void inject_one(ServedMpm& served) {
  const double volume = 0.0625 * 0.0625 * 0.0625 / 4;
  // e = p / ((gamma - 1) rho)
  inject(served,
         {{9000001}, {0.51, 0.2, 0.03}, {10.0, 0.0, 0.0}, {volume}, {volume}, {volume * 2.5e5}});
}

/// Injects 24 hot particles of the coupler's (ids 9100000...) spread over the
/// air: enough that their sums, added after the others, round differently
/// from a fresh map's.
void inject_spread(ServedMpm& served) {
  constexpr std::size_t n = 24;
  Injection in{std::vector<std::uint64_t>(n),   std::vector<double>(3 * n),
               std::vector<double>(3 * n, 0.0), std::vector<double>(n),
               std::vector<double>(n),          std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    in.id[i] = 9100000 + i;
    in.position[3 * i] = 0.27 + 0.019 * static_cast<double>(i);
    in.position[3 * i + 1] = 0.05 + 0.037 * static_cast<double>(i);
    in.position[3 * i + 2] = 0.03;
    in.velocity[3 * i] = 20.0 + static_cast<double>(i);
    in.volume[i] = 0.0625 * 0.0625 * 0.0625 / 4;
    in.mass[i] = 1.3 * in.volume[i];
    in.energy[i] = in.mass[i] * 3.1e5;
  }
  inject(served, in);
}

cosim::Message export_all(ServedMpm& served) {
  cosim::Message message;
  add_export(message, "all");
  add_export(message, "ghost_nodes");
  return served.request(std::move(message));
}

class MpmServeCheckpoint : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("mpfd-mpm-serve-checkpoint-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(MpmServeCheckpoint, ARestoredZoneContinuesBitForBit) {
  ServedMpm first;
  Clock clock{0.0, first.request(setup(blast_text(), regions_with_all(), dir_.string()))
                       .header.setup_ack()
                       .stable_dt()};
  run(first, clock, 10);
  inject_one(first);
  run(first, clock, 5);
  cosim::Message checkpoint;
  checkpoint.header.mutable_checkpoint();
  const auto written = first.request(std::move(checkpoint)).header.checkpoint_written();
  EXPECT_THAT(written.path(), HasSubstr("checkpoint_000015.h5"));
  EXPECT_EQ(written.step(), 15U);  // what Restore must name
  EXPECT_TRUE(std::filesystem::is_regular_file(written.path() + ".sha256"));
  const Clock at_checkpoint = clock;
  run(first, clock, 10);
  const auto expected = export_all(first);
  first.shut_down();

  ServedMpm second;
  second.request(setup(blast_text(), regions_with_all(), dir_.string()));
  cosim::Message restore;
  restore.header.mutable_restore()->set_path(written.path());
  restore.header.mutable_restore()->set_step(15);
  const auto restored = second.request(std::move(restore)).header.restored();
  EXPECT_EQ(restored.step(), 15U);
  EXPECT_EQ(restored.time(), at_checkpoint.time);
  EXPECT_EQ(restored.stable_dt(), at_checkpoint.dt);
  Clock again = at_checkpoint;
  run(second, again, 10);
  EXPECT_EQ(again.time, clock.time);
  const auto got = export_all(second);
  for (const char* name : {"position", "velocity", "mass", "volume", "internal_energy", "stress"})
    EXPECT_EQ(array_of(got, "all", name), array_of(expected, "all", name)) << name;
  EXPECT_EQ(array_of<std::uint64_t>(got, "all", "id"),
            array_of<std::uint64_t>(expected, "all", "id"));
  EXPECT_EQ(array_of(got, "ghost_nodes", "momentum"),
            array_of(expected, "ghost_nodes", "momentum"));
  EXPECT_EQ(second.shut_down().steps_done(), 25U);
}

class MpmServeRestart : public MpmServeCheckpoint {
 protected:
  using Phase = std::function<void(ServedMpm&, Clock&)>;
  /// A zone runs `before` (`steps` advances), checkpoints, runs `after`; a second
  /// zone restored from the checkpoint runs `after` too: both end with the same
  /// particles and ghost nodes.
  void expect_bit_for_bit(std::uint64_t steps, const Phase& before, const Phase& after) {
    ServedMpm first;
    Clock clock{0.0, first.request(setup(blast_text(), regions_with_all(), dir_.string()))
                         .header.setup_ack()
                         .stable_dt()};
    before(first, clock);
    cosim::Message checkpoint;
    checkpoint.header.mutable_checkpoint();
    const auto written = first.request(std::move(checkpoint)).header.checkpoint_written();
    const Clock at_checkpoint = clock;
    after(first, clock);
    const auto expected = export_all(first);
    first.shut_down();

    ServedMpm second;
    second.request(setup(blast_text(), regions_with_all(), dir_.string()));
    cosim::Message restore;
    restore.header.mutable_restore()->set_path(written.path());
    restore.header.mutable_restore()->set_step(steps);
    second.request(std::move(restore));
    Clock again = at_checkpoint;
    after(second, again);
    EXPECT_EQ(again.time, clock.time);
    const auto got = export_all(second);
    for (const char* name : {"position", "velocity", "internal_energy", "stress"})
      EXPECT_EQ(array_of(got, "all", name), array_of(expected, "all", name)) << name;
    EXPECT_EQ(array_of(got, "ghost_nodes", "mass"), array_of(expected, "ghost_nodes", "mass"));
    EXPECT_EQ(array_of(got, "ghost_nodes", "momentum"),
              array_of(expected, "ghost_nodes", "momentum"));
  }
};

// A checkpoint taken while the next step is mapped (the ghost_nodes export
// maps it, and particles injected before the advance are added to that map
// after the others): the restored zone maps it again, so an injection after
// the restore sums in the same order and the run continues bit for bit.
TEST_F(MpmServeRestart, AZoneWhoseNextStepWasMappedContinuesBitForBit) {
  expect_bit_for_bit(
      6, [](ServedMpm& zone, Clock& clock) { run_exporting_ghost_nodes(zone, clock, 6); },
      [](ServedMpm& zone, Clock& clock) {
        inject_spread(zone);
        run_exporting_ghost_nodes(zone, clock, 6);
      });
}

// Particles injected onto the map before a checkpoint: a restore cannot remake
// that map (it would sum them in colour order), so the checkpoint drops it and
// both zones map the next step afresh.
TEST_F(MpmServeRestart, ACheckpointAfterAnInjectionOntoTheMapContinuesBitForBit) {
  expect_bit_for_bit(
      6,
      [](ServedMpm& zone, Clock& clock) {
        run_exporting_ghost_nodes(zone, clock, 6);
        inject_spread(zone);
      },
      [](ServedMpm& zone, Clock& clock) { run_exporting_ghost_nodes(zone, clock, 6); });
}

// A dormant zone woken at t = 2.5 ms starts its clock there (proto §5); a
// checkpoint it takes later restores into a fresh dormant zone of the same
// Setup, which then stands at the checkpoint's time, awake.
TEST_F(MpmServeCheckpoint, AZoneWokenLaterRestoresItsClockIntoAFreshDormantZone) {
  ServedMpm first;
  first.request(setup(blast_text(), regions_with_all(), dir_.string(), true));
  first.hub().set_clock(7, 2.5e-3);
  cosim::Message wake;
  wake.header.mutable_activate()->set_reason("test");
  Clock clock{2.5e-3, first.request(std::move(wake)).header.activate_ack().stable_dt()};
  run(first, clock, 5);
  cosim::Message checkpoint;
  checkpoint.header.mutable_checkpoint();
  const auto written = first.request(std::move(checkpoint)).header.checkpoint_written();
  const Clock at_checkpoint = clock;
  run(first, clock, 5);
  const auto expected = export_all(first);
  first.shut_down();

  ServedMpm second;
  second.request(setup(blast_text(), regions_with_all(), dir_.string(), true));
  cosim::Message restore;
  restore.header.mutable_restore()->set_path(written.path());
  restore.header.mutable_restore()->set_step(5);
  EXPECT_EQ(second.request(std::move(restore)).header.restored().time(), at_checkpoint.time);
  Clock again = at_checkpoint;
  run(second, again, 5);
  EXPECT_EQ(again.time, clock.time);
  EXPECT_EQ(array_of(export_all(second), "all", "position"), array_of(expected, "all", "position"));
}

TEST_F(MpmServeCheckpoint, ACorruptedCheckpointIsRefusedAndTheStateKept) {
  ServedMpm served;
  Clock clock{0.0, served.request(setup(blast_text(), regions_with_all(), dir_.string()))
                       .header.setup_ack()
                       .stable_dt()};
  run(served, clock, 3);
  cosim::Message checkpoint;
  checkpoint.header.mutable_checkpoint()->set_path("cp");
  const auto written = served.request(std::move(checkpoint)).header.checkpoint_written();
  {
    std::fstream file(written.path(), std::ios::in | std::ios::out | std::ios::binary);
    file.seekp(static_cast<std::streamoff>(written.bytes() / 2));
    file.put('\x5a');
  }
  run(served, clock, 2);
  cosim::Message restore;
  restore.header.mutable_restore()->set_path(written.path());
  restore.header.mutable_restore()->set_step(3);
  EXPECT_THAT(served.refusal(std::move(restore)), HasSubstr("SHA-256"));
  run(served, clock, 1);  // non-fatal: the zone carries on from step 5
  EXPECT_EQ(served.shut_down().steps_done(), 6U);
}

// The snapshot series resumes after the particles are restored; where it
// cannot (here a file stands where the snapshots folder goes), the zone holds
// the checkpoint's particles with its Setup's snapshot state: the error is
// fatal, not a refusal the coupler could step on from.
TEST_F(MpmServeCheckpoint, ARestoreThatFailsAfterReplacingTheParticlesStopsTheSolver) {
  const auto first_dir = dir_ / "first", second_dir = dir_ / "second";
  ServedMpm first;
  Clock clock{0.0, first.request(setup(blast_text(), regions_with_all(), first_dir.string()))
                       .header.setup_ack()
                       .stable_dt()};
  run(first, clock, 3);
  cosim::Message output;
  output.header.mutable_write_output();
  first.request(std::move(output));
  cosim::Message checkpoint;
  checkpoint.header.mutable_checkpoint()->set_path("cp");
  const auto written = first.request(std::move(checkpoint)).header.checkpoint_written();
  first.shut_down();

  std::filesystem::create_directories(second_dir);
  std::ofstream(second_dir / "snapshots") << "not a folder";
  ServedMpm second;
  second.request(setup(blast_text(), regions_with_all(), second_dir.string()));
  cosim::Message restore;
  restore.header.mutable_restore()->set_path(written.path());
  restore.header.mutable_restore()->set_step(3);
  EXPECT_THAT(second.refusal(std::move(restore)),
              AllOf(HasSubstr("failed after the state was replaced"),
                    HasSubstr("neither its Setup's nor the checkpoint's")));
  EXPECT_THAT(second.stop_reason(), HasSubstr("ERROR_CODE_IO"));
}

}  // namespace
}  // namespace mpfd::mpm
