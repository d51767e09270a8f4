// Whole fields in chunks (proto/README.md §15): slicing within a byte budget and
// an assembly that restores the fields exactly or names what arrived wrong.
#include "cosim/serving/field_stream.hpp"

#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

#include "cosim/arrays.hpp"
#include "cosim/serving/protocol_error.hpp"

namespace mpfd::cosim {
namespace {

/// Two fields of a region "cells": rho [n] and momentum [n, 3], values distinct per entry.
Message region_fields(std::size_t n) {
  std::vector<double> rho(n);
  std::vector<double> momentum(3 * n);
  std::iota(rho.begin(), rho.end(), 1.0);
  std::iota(momentum.begin(), momentum.end(), -7.5);
  Message message;
  add_array(message, {"cells", "rho", {n}, "kg/m^3"}, std::span<const double>(rho));
  add_array(message, {"cells", "momentum", {n, 3}, "kg*m/s"}, std::span<const double>(momentum));
  return message;
}

const std::vector<std::string> kNames = {"cells/rho", "cells/momentum"};

std::vector<double> values(const Message& message, const std::string& group,
                           const std::string& name) {
  const auto view = view_array<double>(message, group, name);
  return {view.values().begin(), view.values().end()};
}

TEST(FieldStream, SlicesRowsWithinBudgetAndMarksOnlyTheLastChunk) {
  const Message fields = region_fields(10);
  const auto chunks = slice_into_chunks(fields, "t1", kNames, 4 * sizeof(double));
  // rho: 4 rows per chunk -> 3 chunks; momentum rows are 24 bytes -> 1 row per chunk -> 10.
  ASSERT_EQ(chunks.size(), 13u);
  for (std::size_t i = 0; i < chunks.size(); ++i) {
    const auto& body = chunks[i].header.field_chunk();
    EXPECT_EQ(body.chunk_index(), i);
    EXPECT_EQ(body.last(), i + 1 == chunks.size());
    EXPECT_LE(chunks[i].frames.at(0).size(), std::max<std::size_t>(4 * sizeof(double), 24));
  }
  EXPECT_EQ(chunks[2].header.field_chunk().offset(), 8u);
  EXPECT_EQ(chunks[3].header.field_chunk().field(), "cells/momentum");
}

TEST(FieldStream, AssemblyRestoresTheFieldsBitForBitForAnyBudget) {
  const Message fields = region_fields(37);
  for (const std::uint64_t budget :
       {std::uint64_t{1}, std::uint64_t{7 * 8}, std::uint64_t{1} << 26}) {
    FieldAssembly assembly("t2");
    for (const auto& chunk : slice_into_chunks(fields, "t2", kNames, budget)) assembly.add(chunk);
    ASSERT_TRUE(assembly.complete()) << "budget " << budget;
    const Message whole = assembly.take();
    EXPECT_EQ(values(whole, "cells", "rho"), values(fields, "cells", "rho"));
    EXPECT_EQ(values(whole, "cells", "momentum"), values(fields, "cells", "momentum"));
    const auto& momentum = find_descriptor(whole, "cells", "momentum");
    ASSERT_EQ(momentum.shape_size(), 2);
    EXPECT_EQ(momentum.shape(1), 3u);
    EXPECT_EQ(momentum.units(), "kg*m/s");
  }
}

TEST(FieldStream, ZeroRowFieldStillSendsItsShape) {
  const Message fields = region_fields(0);
  const auto chunks = slice_into_chunks(fields, "t3", kNames, 1024);
  ASSERT_EQ(chunks.size(), 2u);
  FieldAssembly assembly("t3");
  for (const auto& chunk : chunks) assembly.add(chunk);
  const Message whole = assembly.take();
  const auto& momentum = find_descriptor(whole, "cells", "momentum");
  EXPECT_EQ(momentum.shape(0), 0u);
  EXPECT_EQ(momentum.shape(1), 3u);
}

TEST(FieldStream, AFieldThatIsNotInTheRegionArraysIsNamed) {
  const Message fields = region_fields(3);
  const std::vector<std::string> names = {"cells/E"};
  EXPECT_THROW(
      {
        try {
          (void)slice_into_chunks(fields, "t4", names, 64);
        } catch (const Error& error) {
          EXPECT_NE(std::string(error.what()).find("'E'"), std::string::npos) << error.what();
          throw;
        }
      },
      Error);
  const std::vector<std::string> unqualified = {"rho"};
  EXPECT_THROW((void)slice_into_chunks(fields, "t4", unqualified, 64), Error);
}

TEST(FieldStream, TheSlicerFindsABadNameBeforeMakingAnyChunk) {
  const Message fields = region_fields(3);
  const std::vector<std::string> names = {"cells/rho", "cells/E"};  // the second is absent
  EXPECT_THROW((void)ChunkSlicer(fields, "t7", names, 64), Error);
}

TEST(FieldStream, TheSlicerMakesOneChunkPerCallAndThenNothing) {
  const Message fields = region_fields(10);
  const auto whole = slice_into_chunks(fields, "t8", kNames, 4 * sizeof(double));
  ChunkSlicer slicer(fields, "t8", kNames, 4 * sizeof(double));
  FieldAssembly assembly("t8");
  std::size_t made = 0;
  while (auto chunk = slicer.next()) {
    ASSERT_LT(made, whole.size());
    EXPECT_EQ(chunk->header.field_chunk().chunk_index(), made);
    EXPECT_EQ(chunk->header.field_chunk().last(), made + 1 == whole.size());
    assembly.add(*chunk);
    ++made;
  }
  EXPECT_EQ(made, whole.size());
  EXPECT_FALSE(slicer.next().has_value());
  const Message back = assembly.take();
  EXPECT_EQ(values(back, "cells", "momentum"), values(fields, "cells", "momentum"));
}

/// A frame's buffer that says when the frame lets it go.
struct WatchedBuffer {
  std::vector<double> values;
  bool* freed;
};

void release_watched(void* /*data*/, void* hint) {
  auto* buffer = static_cast<WatchedBuffer*>(hint);
  *buffer->freed = true;
  delete buffer;
}

/// Appends field "cells/<quantity>" of `rows` values whose buffer sets `freed` when released.
void add_watched_field(Message& message, const std::string& quantity, std::size_t rows,
                       bool& freed) {
  auto* buffer = new WatchedBuffer{std::vector<double>(rows, 2.5), &freed};
  zmq::message_t frame(buffer->values.data(), rows * sizeof(double), release_watched, buffer);
  append_frame(message, {"cells", quantity, {rows}, "Pa"}, v1::DTYPE_F64, rows, std::move(frame));
}

TEST(FieldStream, AnOwningSlicerFreesEachFieldOnceItsLastChunkIsMade) {
  bool p_freed = false;
  bool q_freed = false;
  Message fields;
  add_watched_field(fields, "p", 4, p_freed);
  add_watched_field(fields, "q", 4, q_freed);
  const std::vector<std::string> names = {"cells/p", "cells/q"};
  ChunkSlicer slicer(std::move(fields), "w", names, 2 * sizeof(double));  // 2 chunks a field
  FieldAssembly assembly("w");
  const auto take = [&] {
    auto chunk = slicer.next();
    ASSERT_TRUE(chunk.has_value());
    assembly.add(*chunk);
  };
  ASSERT_NO_FATAL_FAILURE(take());
  EXPECT_FALSE(p_freed) << "p freed before its last chunk";
  ASSERT_NO_FATAL_FAILURE(take());
  EXPECT_TRUE(p_freed) << "p kept after its last chunk";
  EXPECT_FALSE(q_freed);
  ChunkSlicer moved = std::move(slicer);  // as an export hands its slicer to the serve loop
  while (auto chunk = moved.next()) assembly.add(*chunk);
  EXPECT_TRUE(q_freed);
  const Message back = assembly.take();
  EXPECT_EQ(values(back, "cells", "q"), std::vector<double>(4, 2.5));
}

TEST(FieldStream, AnOwningSlicerCutsTheSameChunksAsABorrowingOne) {
  const Message fields = region_fields(7);
  const auto borrowed = slice_into_chunks(fields, "o", kNames, 5 * sizeof(double));
  ChunkSlicer owning(region_fields(7), "o", kNames, 5 * sizeof(double));
  std::size_t i = 0;
  while (auto chunk = owning.next()) {
    ASSERT_LT(i, borrowed.size());
    EXPECT_EQ(chunk->header.SerializeAsString(), borrowed[i].header.SerializeAsString()) << i;
    ASSERT_EQ(chunk->frames.size(), 1U);
    EXPECT_EQ(chunk->frames[0], borrowed[i].frames[0]) << "chunk " << i;
    ++i;
  }
  EXPECT_EQ(i, borrowed.size());
}

TEST(FieldStream, AFieldNamedTwiceIsRefusedBeforeAnyChunk) {
  const Message fields = region_fields(3);
  const std::vector<std::string> names = {"cells/rho", "cells/momentum", "cells/rho"};
  try {
    (void)ChunkSlicer(fields, "t9", names, 64);
    FAIL() << "a field named twice was sliced";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'cells/rho' is named twice"), std::string::npos)
        << error.what();
  }
}

/// The MALFORMED message of adding `chunks` in order, or "" if none threw.
std::string first_malformed(const std::string& transfer, const std::vector<Message>& chunks) {
  FieldAssembly assembly(transfer);
  try {
    for (const auto& chunk : chunks) assembly.add(chunk);
    (void)assembly.take();
  } catch (const ProtocolError& error) {
    EXPECT_EQ(error.code(), v1::ERROR_CODE_MALFORMED);
    return error.what();
  }
  return "";
}

TEST(FieldAssembly, RejectsAGapOrOverlapByFieldAndOffset) {
  const Message fields = region_fields(6);
  const auto chunks = [&fields] { return slice_into_chunks(fields, "t5", kNames, 16); };
  ASSERT_TRUE(first_malformed("t5", chunks()).empty());

  auto gap = chunks();
  gap[1].header.mutable_field_chunk()->set_offset(4);
  EXPECT_NE(first_malformed("t5", gap).find("offset 4, expected 2"), std::string::npos);

  auto dropped = chunks();  // rho loses its last chunk; momentum follows
  dropped.erase(dropped.begin() + 2);
  for (std::size_t i = 2; i < dropped.size(); ++i)
    dropped[i].header.mutable_field_chunk()->set_chunk_index(static_cast<std::uint32_t>(i));
  const std::string short_field = first_malformed("t5", dropped);
  EXPECT_NE(short_field.find("'cells/rho'"), std::string::npos) << short_field;
  EXPECT_NE(short_field.find("4 of 6 rows"), std::string::npos) << short_field;

  auto reordered = chunks();
  std::swap(reordered[0], reordered[1]);
  EXPECT_NE(first_malformed("t5", reordered).find("chunk_index 1, expected 0"), std::string::npos);

  auto truncated = chunks();
  truncated.pop_back();
  EXPECT_NE(first_malformed("t5", truncated).find("incomplete"), std::string::npos);

  EXPECT_NE(first_malformed("other", chunks()).find("while assembling 'other'"), std::string::npos);
}

TEST(FieldAssembly, RejectsAChunkAfterTheLast) {
  const Message fields = region_fields(2);
  const auto chunks = slice_into_chunks(fields, "t6", kNames, 1 << 20);
  FieldAssembly assembly("t6");
  for (const auto& chunk : chunks) assembly.add(chunk);
  EXPECT_THROW(assembly.add(chunks.back()), ProtocolError);
}

}  // namespace
}  // namespace mpfd::cosim
