// Checkpoint and Restore of a two-material zone (TNT products and air, with
// tracers): run A takes 12 steps, checkpoints, takes 8 more; run B restores
// the checkpoint into a fresh zone and takes the same 8 steps. Every cell
// field, tracer, per-material state and boundary outflow must be bitwise the
// same.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

#include "checkpoint_support.hpp"
#include "cosim/serving/sha256.hpp"
#include "fdm_solver/serve/checkpoint.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;

/// The count of cells that hold no tracer (their material came from fill_empty_cells).
std::size_t empty_cells(const MultiMaterialTracker& tracker) {
  std::size_t empty = 0;
  for (std::size_t c = 0; c < tracker.bins().cell_count(); ++c)
    empty += tracker.bins().count(c) == 0;
  return empty;
}

TEST(FdmCheckpointMultiMaterial,
     RestoredAtStepTwelveAndAdvancedEightStepsEqualsTheUninterruptedRunBitwise) {
  const TempDir dir("two-materials");
  const std::string scene = corner_charge_text(20, 20);
  const auto a = zone_of(scene, dir.path());
  ASSERT_NE(a->solver.tracker(), nullptr);
  const std::size_t seeded = a->solver.tracker()->tracers().size();
  advance_stable(*a, 12);
  const SolverImage at_twelve(a->solver);
  // The state holds what a partial checkpoint would miss: mixed cells (their
  // e_r, rho_r) and cells without tracers (their filled classification).
  EXPECT_GT(a->solver.last_closure().mixed_cells, 0U);
  EXPECT_GT(empty_cells(*a->solver.tracker()), 0U);
  // ... and the outflow per boundary cell that a region's outflow_* reports
  // (the air's pressure impulse on the open faces from the first step on).
  const auto& x_upper = at_twelve.face_outflow[static_cast<std::size_t>(config::Face::x_upper)];
  EXPECT_TRUE(std::any_of(x_upper.begin(), x_upper.end(), [](double v) { return v != 0.0; }));
  const auto written = write_checkpoint(*a, {});
  const std::filesystem::path file = dir.path() / "checkpoints" / "checkpoint_000012.h5";
  ASSERT_EQ(written.path(), file.string());
  EXPECT_EQ(written.bytes(), std::filesystem::file_size(file));
  EXPECT_EQ(written.sha256(), cosim::sha256_hex_of_file(file));
  std::ifstream sidecar(file.string() + ".sha256");
  std::string digest, name;
  sidecar >> digest >> name;
  EXPECT_EQ(digest, written.sha256());
  EXPECT_EQ(name, "checkpoint_000012.h5");
  // 218 kB: 136 bytes of arrays per cell, 40 per tracer, 40 per boundary cell
  // of the 4 faces of the plane, and HDF5's metadata.
  const std::size_t arrays = 136 * 400 + 40 * a->solver.tracker()->tracers().size() + 40 * 80;
  EXPECT_GT(written.bytes(), arrays);
  EXPECT_LT(written.bytes(), arrays + 32 * 1024);
  RecordProperty("checkpoint_bytes", std::to_string(written.bytes()));
  advance_stable(*a, 8);
  EXPECT_LT(a->solver.tracker()->tracers().size(), seeded) << "no tracer left through a face";

  const auto b = zone_of(scene);
  cosim::v1::Restore request;
  request.set_path(file.string());
  request.set_step(12);
  const auto restored = restore_checkpoint(*b, request);
  EXPECT_EQ(restored.step(), 12U);
  EXPECT_EQ(restored.time(), at_twelve.time);
  EXPECT_TRUE(SolverImage(b->solver) == at_twelve);
  advance_stable(*b, 8);
  const SolverImage resumed(b->solver), uninterrupted(a->solver);
  EXPECT_EQ(resumed.u, uninterrupted.u);
  EXPECT_EQ(resumed.material, uninterrupted.material);
  EXPECT_EQ(resumed.mix_gamma, uninterrupted.mix_gamma);
  EXPECT_EQ(resumed.mix_pinf, uninterrupted.mix_pinf);
  EXPECT_EQ(resumed.tracer_position, uninterrupted.tracer_position);
  EXPECT_EQ(resumed.tracer_material, uninterrupted.tracer_material);
  EXPECT_EQ(resumed.tracer_volume, uninterrupted.tracer_volume);
  EXPECT_EQ(resumed.theta, uninterrupted.theta);
  EXPECT_EQ(resumed.material_energy, uninterrupted.material_energy);
  EXPECT_EQ(resumed.cell_energy, uninterrupted.cell_energy);
  EXPECT_EQ(resumed.face_outflow, uninterrupted.face_outflow);
  EXPECT_TRUE(resumed == uninterrupted);
}

}  // namespace
}  // namespace mpfd::fdm
