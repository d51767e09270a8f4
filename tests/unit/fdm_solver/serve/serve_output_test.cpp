// WriteOutput and SampleGauges of fdm_solver serve: what a coupler reads
// back matches the solver's cells.

#include <gtest/gtest.h>

#include <filesystem>

#include "checkpoint_support.hpp"
#include "common/io/hdf5_file.hpp"
#include "serve_harness.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;

TEST(FdmServe, WriteOutputSnapshotHoldsTheExportedDensityInTheDocumentedLayout) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("mpfd-fdm-serve-output-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  ServedFdm fdm;
  fdm.request(setup(sod_text(20), {cell_box("tube", {0}, {20}, {"rho"})}, dir.string()));
  const double dt = 1e-3;
  cosim::Message exchange;
  add_advance(exchange, dt, 0.0);
  add_export(exchange, "tube");
  const auto rho = array_of(fdm.request(std::move(exchange)), "tube", "rho");

  cosim::Message write;
  write.header.mutable_write_output()->add_fields("density");
  const auto written = fdm.request(std::move(write)).header.output_written();
  ASSERT_EQ(written.files_size(), 2);
  EXPECT_EQ(written.files(0), (dir / "snapshots" / "snapshot_000000.h5").string());
  EXPECT_TRUE(std::filesystem::exists(dir / "cells.xmf"));
  const io::Hdf5File h5(written.files(0), io::Hdf5File::Mode::read);
  EXPECT_EQ(h5.read_attribute("/", "time"), dt);
  EXPECT_EQ(h5.read_attribute("/", "step"), 1.0);
  const auto density = h5.read_dataset("/cells/density");
  EXPECT_EQ(density.shape, (std::vector<std::size_t>{1, 1, 20}));
  EXPECT_EQ(density.values, rho);
  std::filesystem::remove_all(dir);
}

// A multi-material zone's snapshot holds its tracers as particles, as
// `fdm_solver run` writes them (docs/output.md): position, material, volume.
TEST(FdmServe, WriteOutputOfAMultiMaterialZoneHoldsItsTracers) {
  const TempDir dir("output-tracers");
  auto zone = zone_of(corner_charge_text(8, 8), dir.path());
  advance_stable(*zone, 3);
  const auto written = zone->output.write(zone->solver, zone->time(), cosim::v1::WriteOutput{});
  ASSERT_EQ(written.files_size(), 3);
  EXPECT_EQ(written.files(2), (dir.path() / "particles.xmf").string());
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "particles.xmf"));
  const TracerSet& tracers = zone->solver.tracker()->tracers();
  ASSERT_GT(tracers.material.size(), 0U);
  const io::Hdf5File h5(written.files(0), io::Hdf5File::Mode::read);
  const auto position = h5.read_dataset("/particles/position");
  const auto material = h5.read_dataset("/particles/material");
  const auto volume = h5.read_dataset("/particles/volume");
  ASSERT_EQ(material.values.size(), tracers.material.size());
  EXPECT_EQ(volume.values, tracers.volume);
  for (std::size_t k = 0; k < tracers.material.size(); ++k) {
    EXPECT_EQ(material.values[k], static_cast<double>(tracers.material[k])) << k;
    for (std::size_t a = 0; a < 3; ++a)
      EXPECT_EQ(position.values[3 * k + a], tracers.position[a][k]) << k;
  }
}

TEST(FdmServe, SampleGaugesReadsTheCellHoldingEachGauge) {
  ServedFdm fdm;
  fdm.request(setup(sod_text(10), {}));
  cosim::Message exchange;
  auto& sample = *exchange.header.mutable_exchange()->add_operations()->mutable_sample();
  sample.set_group("gauges");
  // x only: the tube's y and z have one cell. 0.45 is in cell 4 (left state), 0.95 in cell 9.
  for (const char* name : {"left", "right"}) sample.add_gauge_names(name);
  for (const double x : {0.45, 0.95}) sample.add_positions(x);
  for (const char* q : {"rho", "velocity_x"}) sample.add_quantities(q);
  const auto reply = fdm.request(std::move(exchange));
  EXPECT_EQ(reply.header.exchange_result().results(0).sampled().count(), 2U);
  EXPECT_EQ(array_of(reply, "gauges", "rho"), (std::vector<double>{1.0, 0.125}));
  EXPECT_EQ(array_of(reply, "gauges", "velocity_x"), (std::vector<double>{0.0, 0.0}));
}

}  // namespace
}  // namespace mpfd::fdm
