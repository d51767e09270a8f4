// Whole-field transfers (proto/README.md §15) with the real `fdm_solver serve`
// executable over ipc: the two-material corner charge's state and tracers are
// exported in 16 KiB chunks, imported back into the same solver at a later
// sim_time, and the next step from that time is bitwise the solver's own.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "child_process.hpp"
#include "common/config/scene_loader.hpp"
#include "cosim/serving/field_stream.hpp"
#include "tests/unit/fdm_solver/serve/field_transfer_support.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;
using std::chrono::milliseconds;

TEST(FdmServeFieldTransfer, ExportImportRoundTripOverIpcThenAStepBitwiseAsTheSolverDirectly) {
  zmq::context_t context;
  cosim::TransportOptions options;
  options.reply_timeout = milliseconds{10000};  // covers the child's start-up
  cosim::Hub hub(context, cosim::testing::unique_bind_endpoint(cosim::Transport::ipc), options);
  auto solver = mpfd::testing::start_serve(MPFD_FDM_SOLVER, hub.endpoint(), "10", "fields");
  const std::vector<std::string> peers{"fdm"};
  const auto hello = hub.accept(peers, "run-fields").front();
  for (const char* capability : {"field_chunks", "tracer_regions", "material_fields"})
    EXPECT_THAT(hello.capabilities(), ::testing::Contains(capability));
  const std::string scene = corner_charge_text(kNx, kNy);
  hub.send("fdm", setup(scene, transfer_regions()));
  (void)hub.receive_from("fdm");

  cosim::Message request = export_request("out", kStateFields, 16 << 10);
  hub.send("fdm", std::move(request));
  cosim::FieldAssembly assembly("out");
  std::vector<cosim::Message> chunks;
  do {
    chunks.push_back(hub.receive_from("fdm"));
    assembly.add(chunks.back());
  } while (!chunks.back().header.field_chunk().last());
  EXPECT_GT(chunks.size(), kStateFields.size());
  const cosim::Message fields = assembly.take();

  // The same state directly: rho in box C order (j fastest) from grid order.
  const auto parsed = config::parse_scene(scene, "corner.yaml");
  EulerSolver direct(parsed, SolverOptions::from_scene(parsed));
  const auto rho = array_of(fields, "all_cells", "rho");
  for (int i = 0; i < kNx; ++i)
    for (int j = 0; j < kNy; ++j)
      ASSERT_EQ(rho[static_cast<std::size_t>(i * kNy + j)],
                direct.state().u[kDensity][direct.state().grid.cell_index(i, j, 0)]);
  EXPECT_EQ(cosim::find_descriptor(fields, "all_tracers", "position").shape(0),
            direct.tracker()->tracers().size());

  const double handoff_time = 1.0e-6;
  for (auto& chunk : chunks) {
    chunk.header.clear_envelope();
    hub.send("fdm", std::move(chunk));
    ASSERT_TRUE(hub.receive_from("fdm").header.has_field_chunk_ack());
  }
  hub.set_clock(1, handoff_time);
  hub.send("fdm", commit_request("out", true, 0.0));
  const auto done = hub.receive_from("fdm").header.field_import_done();
  EXPECT_EQ(done.stable_dt(), direct.stable_dt());
  const Totals totals = direct.totals();
  ASSERT_EQ(done.totals_size(), 5);
  for (int v = 0; v < 5; ++v) EXPECT_EQ(done.totals(v), totals[static_cast<std::size_t>(v)]);

  cosim::Message step;
  add_advance(step, done.stable_dt(), handoff_time);
  add_export(step, "all_cells");
  hub.send("fdm", std::move(step));
  const cosim::Message stepped = hub.receive_from("fdm");
  direct.advance(done.stable_dt());
  const auto energy = array_of(stepped, "all_cells", "E");
  for (int i = 0; i < kNx; ++i)
    for (int j = 0; j < kNy; ++j)
      ASSERT_EQ(energy[static_cast<std::size_t>(i * kNy + j)],
                direct.state().u[kEnergy][direct.state().grid.cell_index(i, j, 0)]);

  cosim::Message shutdown;
  shutdown.header.mutable_shutdown()->set_reason("test done");
  hub.send("fdm", std::move(shutdown));
  (void)hub.receive_from("fdm");
  EXPECT_EQ(solver->wait_for(milliseconds{5000}), 0) << solver->error_output();
}

}  // namespace
}  // namespace mpfd::fdm
