// WriteOutput and SampleGauges of fdm_solver serve: what a coupler reads
// back matches the solver's cells.

#include <gtest/gtest.h>

#include <filesystem>

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
