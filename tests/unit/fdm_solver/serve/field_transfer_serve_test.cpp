// Whole-field transfers through `fdm_solver serve` over a transport
// (proto/README.md §15): the export stream answers its request chunk by
// chunk, every imported chunk is acknowledged, and after the commit the next
// Advance starts at the commit's sim_time.

#include <gtest/gtest.h>

#include "field_transfer_support.hpp"

namespace mpfd::fdm {
namespace {

using namespace testing;

/// Sends a FieldExportRequest and collects the chunks until `last`, checking
/// that each replies to the request.
std::vector<cosim::Message> exported(ServedFdm& fdm, const std::vector<std::string>& fields,
                                     std::uint64_t budget) {
  const std::uint64_t sequence = fdm.hub().send("fdm", export_request("x", fields, budget));
  std::vector<cosim::Message> chunks;
  do {
    chunks.push_back(fdm.hub().receive_from("fdm"));
    EXPECT_EQ(chunks.back().header.envelope().in_reply_to(), sequence);
  } while (!chunks.back().header.field_chunk().last());
  return chunks;
}

TEST(FdmFieldTransferServe, ExportStreamImportAndCommitThenAdvanceFromSimTime) {
  std::string scene = corner_charge_text(kNx, kNy);
  ServedFdm source, target;
  source.request(setup(scene, transfer_regions()));
  target.request(setup(scene.substr(0, scene.find("bodies:")), transfer_regions()));
  const auto chunks = exported(source, kStateFields, 4096);
  EXPECT_GT(chunks.size(), kStateFields.size());
  for (const auto& chunk : chunks) {
    cosim::Message copy;
    copy.header = chunk.header;
    copy.header.clear_envelope();
    for (const auto& frame : chunk.frames) copy.frames.emplace_back(frame.data(), frame.size());
    const cosim::Message ack = target.request(std::move(copy));
    ASSERT_TRUE(ack.header.has_field_chunk_ack());
    EXPECT_EQ(ack.header.field_chunk_ack().chunk_index(), chunk.header.field_chunk().chunk_index());
  }
  const double handoff_time = 3.0e-6;
  target.hub().set_clock(0, handoff_time);
  cosim::Message commit;
  commit.header.mutable_field_import_commit()->set_transfer_id("x");
  commit.header.mutable_field_import_commit()->set_tracers(true);
  const cosim::Message done = target.request(std::move(commit));
  ASSERT_TRUE(done.header.has_field_import_done());
  const double dt = done.header.field_import_done().stable_dt();
  EXPECT_GT(dt, 0.0);
  EXPECT_EQ(done.header.field_import_done().totals_size(), 5);
  cosim::Message advance;
  add_advance(advance, dt, handoff_time);
  add_export(advance, "all_cells");
  add_export(advance, "all_tracers");
  const cosim::Message stepped = target.request(std::move(advance));
  EXPECT_DOUBLE_EQ(stepped.header.exchange_result().results(0).advanced().time(),
                   handoff_time + dt);
  cosim::Message reference;
  add_advance(reference, dt, 0.0);
  add_export(reference, "all_cells");
  add_export(reference, "all_tracers");
  const cosim::Message expected = source.request(std::move(reference));
  EXPECT_EQ(array_of(stepped, "all_cells", "E"), array_of(expected, "all_cells", "E"));
  EXPECT_EQ(stepped.header.exchange_result().results(2).exported().count(),
            static_cast<std::uint64_t>(kNx * kNy * 9));  // 3 x 3 tracers per cell
  EXPECT_EQ(array_of(stepped, "all_tracers", "position"),
            array_of(expected, "all_tracers", "position"));
}

}  // namespace
}  // namespace mpfd::fdm
