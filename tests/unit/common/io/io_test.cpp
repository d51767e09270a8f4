#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "common/core/error.hpp"
#include "common/io/gauge_recorder.hpp"
#include "common/io/hdf5_file.hpp"
#include "common/io/output_directory.hpp"
#include "common/io/run_summary.hpp"
#include "common/io/snapshot_writer.hpp"

namespace mpfd::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

class OutputFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("mpfd_io_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

TEST_F(OutputFolder, SnapshotRoundTripsCellFieldsInZYXOrderWithUnits) {
  const auto grid = grid::UniformGrid::from_bounds({0, 0, 0}, {0.4, 0.3, 0.1}, {4, 3, 1});
  std::vector<double> rho(grid.cell_count()), u(grid.cell_count()), v(grid.cell_count()),
      w(grid.cell_count(), 0.0);
  for (std::size_t n = 0; n < rho.size(); ++n) {
    rho[n] = 1.0 + double(n);
    u[n] = 10.0 * double(n);
    v[n] = -double(n);
  }
  SnapshotWriter writer(dir_, grid);
  const fs::path file =
      writer.write(7, 1.5e-3, {{"density", "kg/m^3", {rho}}, {"velocity", "m/s", {u, v, w}}});
  EXPECT_EQ(file.filename(), "snapshot_000000.h5");
  EXPECT_FALSE(fs::exists(file.string() + ".tmp"));

  const Hdf5File h5(file, Hdf5File::Mode::read);
  EXPECT_EQ(h5.read_string_attribute("/", "format"), "mpfd-snapshot");
  EXPECT_DOUBLE_EQ(h5.read_attribute("/", "time"), 1.5e-3);
  const auto density = h5.read_dataset("/cells/density");
  EXPECT_THAT(density.shape, ElementsAre(1u, 3u, 4u));
  EXPECT_EQ(density.values, rho);  // x fastest in memory and on disk
  EXPECT_EQ(h5.read_string_attribute("/cells/density", "units"), "kg/m^3");
  const auto velocity = h5.read_dataset("/cells/velocity");
  EXPECT_THAT(velocity.shape, ElementsAre(1u, 3u, 4u, 3u));
  EXPECT_DOUBLE_EQ(velocity.values[3 * 5 + 0], u[5]);
  EXPECT_DOUBLE_EQ(velocity.values[3 * 5 + 1], v[5]);
}

TEST_F(OutputFolder, XdmfSidecarListsEverySnapshotInTime) {
  const auto grid = grid::UniformGrid::from_bounds({0, 0, 0}, {1, 1, 1}, {5, 1, 1});
  const std::vector<double> p(5, 1e5);
  SnapshotWriter writer(dir_, grid);
  writer.write(0, 0.0, {{"pressure", "Pa", {p}}});
  writer.write(10, 2e-4, {{"pressure", "Pa", {p}}});
  const std::string xmf = read_text(dir_ / "cells.xmf");
  EXPECT_THAT(xmf, HasSubstr("<Time Value=\"0.00020000000000000001\"/>"));
  EXPECT_THAT(xmf, HasSubstr("Dimensions=\"2 2 6\""));  // nodes z, y, x
  EXPECT_THAT(xmf, HasSubstr("snapshots/snapshot_000001.h5:/cells/pressure"));
  EXPECT_FALSE(fs::exists(dir_ / "particles.xmf"));
}

TEST_F(OutputFolder, ParticlesNeedAPositionAndAgreeingLengths) {
  const auto grid = grid::UniformGrid::from_bounds({0, 0, 0}, {1, 1, 1}, {2, 2, 2});
  const std::vector<double> x{0.1, 0.2}, y{0.5, 0.5}, z{0.5, 0.5}, m{1.0, 2.0}, bad{1.0};
  SnapshotWriter writer(dir_, grid);
  EXPECT_THROW(writer.write(0, 0.0, {}, {{"mass", "kg", {m}}}), Error);
  EXPECT_THROW(writer.write(0, 0.0, {}, {{"position", "m", {x, y, z}}, {"mass", "kg", {bad}}}),
               Error);
  writer.write(0, 0.0, {}, {{"position", "m", {x, y, z}}, {"mass", "kg", {m}}});
  const std::string xmf = read_text(dir_ / "particles.xmf");
  EXPECT_THAT(xmf, HasSubstr("NumberOfElements=\"2\""));
  EXPECT_THAT(xmf, HasSubstr(":/particles/mass"));
}

TEST_F(OutputFolder, GaugeHistoriesMatchInCsvAndHdf5) {
  GaugeRecorder gauges(dir_, {{"near", {0.1, 0, 0}}, {"far", {0.9, 0, 0}}},
                       {{"pressure", "Pa"}, {"density", "kg/m^3"}});
  gauges.record(0.0, std::vector<double>{1e5, 1.2, 1e5, 1.2});
  gauges.record(1e-6, std::vector<double>{2e5, 1.9, 1e5, 1.2});
  EXPECT_THROW(gauges.record(2e-6, std::vector<double>{1.0}), Error);
  gauges.flush();
  const std::string csv = read_text(dir_ / "gauges.csv");
  EXPECT_THAT(csv, HasSubstr("time[s],near.pressure[Pa],near.density[kg/m^3],far.pressure[Pa]"));
  EXPECT_THAT(csv, HasSubstr("1e-06,200000,1.9,100000,1.2\n"));
  const Hdf5File h5(dir_ / "gauges.h5", Hdf5File::Mode::read);
  EXPECT_THAT(h5.read_dataset("/time").values, ElementsAre(0.0, 1e-6));
  EXPECT_THAT(h5.read_dataset("/gauges/near/pressure").values, ElementsAre(1e5, 2e5));
  EXPECT_THAT(h5.read_dataset("/gauges/far/density").values, ElementsAre(1.2, 1.2));
}

TEST_F(OutputFolder, SummaryCarriesStatusRatesAndConservationVerdict) {
  RunSummary summary("fdm_solver", "sod", "configs/sod.yaml");
  summary.set_progress(120, 2e-4, 2e-4, 0.5);
  summary.set_rate("cell_updates_per_second", 3.0e8);
  summary.set_conservation({{"mass", "kg", 1.0, 0.9, 0.1 + 1e-12}});
  summary.set_status("completed");
  summary.write(dir_ / "summary.json");
  const auto doc = nlohmann::json::parse(read_text(dir_ / "summary.json"));
  EXPECT_EQ(doc["status"], "completed");
  EXPECT_EQ(doc["steps"], 120);
  EXPECT_DOUBLE_EQ(doc["rates"]["cell_updates_per_second"].get<double>(), 3.0e8);
  EXPECT_NEAR(doc["conservation"]["mass"]["relative_error"].get<double>(), 1e-12, 1e-15);
}

TEST_F(OutputFolder, AFinishedRunIsNeverOverwrittenByMistake) {
  RunSummary("fdm_solver", "x", "x.yaml").write(dir_ / "summary.json");
  try {
    prepare_output_directory(dir_, false);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr(dir_.string()));
    EXPECT_THAT(e.what(), HasSubstr("--overwrite"));
  }
  EXPECT_TRUE(fs::exists(dir_ / "summary.json"));
  EXPECT_NO_THROW(prepare_output_directory(dir_, true));
  EXPECT_NO_THROW(prepare_output_directory(dir_ / "fresh" / "nested", false));
}

TEST_F(OutputFolder, ReadingAMissingDatasetNamesFileAndPath) {
  { Hdf5File h5(dir_ / "a.h5", Hdf5File::Mode::create); }
  const Hdf5File h5(dir_ / "a.h5", Hdf5File::Mode::read);
  try {
    (void)h5.read_dataset("/cells/density");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("a.h5"));
    EXPECT_THAT(e.what(), HasSubstr("/cells/density"));
  }
  EXPECT_THROW(Hdf5File(dir_ / "missing.h5", Hdf5File::Mode::read), Error);
}

}  // namespace
}  // namespace mpfd::io
