// FieldExportRequest (proto/README.md §15 rule 2): chunks that reassemble to
// exactly what ExportRegion gives, TRACERS regions and the per-material fields.

#include <gtest/gtest.h>

#include <cmath>

#include "fdm_solver/serve/region_transfer.hpp"
#include "field_transfer_support.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;

TEST(FdmFieldExport, FieldExport_EqualsExportRegionBitForBit_ForChunkSizes_1Row_Odd_Large) {
  const auto zone = transfer_zone();
  advance_stable(*zone, 6);  // mixed cells: theta, rho_r, e_r differ from cell values
  ASSERT_GT(zone->solver.last_closure().mixed_cells, 0U);
  cosim::Message cells, tracers;
  (void)export_region(zone->solver, zone->regions.at("all_cells"), {}, cells);
  (void)export_tracers(zone->solver, *zone->tracer_region("all_tracers"), {}, tracers);
  std::vector<std::string> fields;
  for (const auto& array : cells.header.arrays()) fields.push_back("all_cells/" + array.name());
  fields.push_back("all_tracers/position");
  fields.push_back("all_tracers/material");
  ASSERT_EQ(fields.size(), 10U);
  // 1 byte: one row per chunk; 1000: an odd number of rows of every field; 1 GiB: one chunk each.
  for (const std::uint64_t budget :
       {std::uint64_t{1}, std::uint64_t{1000}, std::uint64_t{1} << 30}) {
    const auto chunks = export_chunks(*zone, export_request("t", fields, budget));
    cosim::FieldAssembly assembly("t");
    for (const auto& chunk : chunks) assembly.add(chunk);
    ASSERT_TRUE(assembly.complete()) << budget;
    const cosim::Message whole = assembly.take();
    for (const auto& array : cells.header.arrays())
      EXPECT_EQ(bytes_of(whole, "all_cells", array.name()),
                bytes_of(cells, "all_cells", array.name()))
          << array.name() << ", budget " << budget;
    for (const char* q : {"position", "material"})
      EXPECT_EQ(bytes_of(whole, "all_tracers", q), bytes_of(tracers, "all_tracers", q))
          << q << ", budget " << budget;
    const std::size_t tracer_count = zone->solver.tracker()->tracers().size();
    const std::size_t cell_count = zone->solver.state().grid.cell_count();
    if (budget == 1) {
      EXPECT_EQ(chunks.size(), 8 * cell_count + 2 * tracer_count);
    }
    if (budget == std::uint64_t{1} << 30) {
      EXPECT_EQ(chunks.size(), fields.size());
    }
  }
}

TEST(FdmFieldExport, TracerRegion_ExportsExactlyTheTracersInItsBox) {
  const auto zone = transfer_zone();
  advance_stable(*zone, 6);
  cosim::Message reply;
  const std::uint64_t count =
      export_tracers(zone->solver, *zone->tracer_region("corner_tracers"), {}, reply);
  // The box [1, 4) x [2, 5) of 1 cm cells, counted here from the positions.
  const TracerSet& all = zone->solver.tracker()->tracers();
  std::vector<double> expected_position;
  std::vector<std::uint32_t> expected_material;
  for (std::size_t t = 0; t < all.size(); ++t) {
    const double i = std::floor(all.position[0][t] / 0.01);
    const double j = std::floor(all.position[1][t] / 0.01);
    if (i < 1 || i >= 4 || j < 2 || j >= 5) continue;
    for (int a = 0; a < 3; ++a) expected_position.push_back(all.position[a][t]);
    expected_material.push_back(static_cast<std::uint32_t>(all.material[t]));
  }
  EXPECT_EQ(count, expected_material.size());
  EXPECT_GT(count, 0U);
  EXPECT_LT(count, all.size());
  EXPECT_EQ(array_of(reply, "corner_tracers", "position"), expected_position);
  const auto material = cosim::view_array<std::uint32_t>(reply, "corner_tracers", "material");
  EXPECT_EQ(std::vector<std::uint32_t>(material.values().begin(), material.values().end()),
            expected_material);
  EXPECT_EQ(material.descriptor().shape_size(), 1);
}

TEST(FdmFieldExport, MaterialFields_SingleMaterialCellHasThetaOne_MixedSumsToOne) {
  const auto zone = transfer_zone();
  advance_stable(*zone, 6);
  cosim::v1::ExportRegion asked;
  for (const char* q : {"cell_material", "volume_fraction", "material_density", "material_energy"})
    asked.add_quantities(q);
  cosim::Message reply;
  (void)export_region(zone->solver, zone->regions.at("all_cells"), asked, reply);
  const auto material = cosim::view_array<std::int32_t>(reply, "all_cells", "cell_material");
  const auto theta = array_of(reply, "all_cells", "volume_fraction");
  const auto rho_r = array_of(reply, "all_cells", "material_density");
  const auto e_r = array_of(reply, "all_cells", "material_energy");
  const EulerState& state = zone->solver.state();
  std::size_t mixed = 0, single = 0;
  // Box C order (j fastest here) against grid order (i fastest).
  for (int i = 0; i < kNx; ++i)
    for (int j = 0; j < kNy; ++j) {
      const std::size_t n = static_cast<std::size_t>(i * kNy + j);
      const std::size_t cell = state.grid.cell_index(i, j, 0);
      const int m = material.values()[n];
      if (m >= 0) {
        ++single;
        const auto r = static_cast<std::size_t>(m);
        EXPECT_EQ(theta[2 * n + r], 1.0);
        EXPECT_EQ(theta[2 * n + 1 - r], 0.0);
        EXPECT_EQ(rho_r[2 * n + r], state.u[kDensity][cell]);
        EXPECT_EQ(e_r[2 * n + r], specific_internal_energy(state, cell));
        continue;
      }
      ++mixed;
      EXPECT_GT(theta[2 * n], 0.0);
      EXPECT_GT(theta[2 * n + 1], 0.0);
      EXPECT_NEAR(theta[2 * n] + theta[2 * n + 1], 1.0, 1e-15) << "cell " << i << ", " << j;
      // The closure conserves the cell's mass: sum theta_r rho_r = rho_c.
      EXPECT_NEAR(theta[2 * n] * rho_r[2 * n] + theta[2 * n + 1] * rho_r[2 * n + 1],
                  state.u[kDensity][cell], 1e-9 * state.u[kDensity][cell]);
    }
  EXPECT_GT(mixed, 0U);
  EXPECT_GT(single, 0U);
}

TEST(FdmFieldExport, MaterialFields_OfAOneMaterialZoneAreThetaOneForItsMaterial) {
  const auto zone = transfer_zone(false);
  ASSERT_EQ(zone->solver.tracker(), nullptr);
  cosim::v1::ExportRegion asked;
  asked.add_quantities("volume_fraction");
  asked.add_quantities("cell_material");
  cosim::Message reply;
  (void)export_region(zone->solver, zone->regions.at("all_cells"), asked, reply);
  const auto theta = array_of(reply, "all_cells", "volume_fraction");
  ASSERT_EQ(theta.size(), 2U * kNx * kNy);
  for (std::size_t n = 0; n < theta.size() / 2; ++n) {
    EXPECT_EQ(theta[2 * n], 1.0);  // air, the scene's material 0
    EXPECT_EQ(theta[2 * n + 1], 0.0);
  }
  cosim::Message tracers;
  EXPECT_EQ(export_tracers(zone->solver, *zone->tracer_region("all_tracers"), {}, tracers), 0U);
  EXPECT_EQ(cosim::find_descriptor(tracers, "all_tracers", "position").shape(1), 3U);
}

TEST(FdmFieldExport, AnUnknownQuantityIsARefusalThatIsNotFatal) {
  const auto zone = transfer_zone();
  try {
    (void)export_fields(*zone, export_request("t", {"all_cells/rho", "all_cells/nonsense"}, 64));
    FAIL() << "no refusal";
  } catch (const cosim::ProtocolError& error) {
    EXPECT_EQ(error.code(), v1::ERROR_CODE_UNKNOWN_REGION);
    EXPECT_FALSE(error.fatal());
    EXPECT_NE(std::string(error.what()).find("nonsense"), std::string::npos) << error.what();
  }
}

TEST(FdmFieldExport, AFieldAskedTwiceIsAMalformedRefusalThatIsNotFatal) {
  const auto zone = transfer_zone();
  try {
    (void)export_fields(*zone, export_request("t", {"all_cells/rho", "all_cells/rho"}, 64));
    FAIL() << "no refusal";
  } catch (const cosim::ProtocolError& error) {
    EXPECT_EQ(error.code(), v1::ERROR_CODE_MALFORMED);
    EXPECT_FALSE(error.fatal());
    EXPECT_NE(std::string(error.what()).find("'all_cells/rho' is named twice"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace mpfd::fdm
