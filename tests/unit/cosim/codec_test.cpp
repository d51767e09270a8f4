#include "cosim/codec.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "common/core/error.hpp"
#include "cosim/arrays.hpp"

namespace mpfd::cosim {
namespace {

Message exchange_with_strip(std::size_t cells) {
  Message message;
  message.header.mutable_envelope()->set_protocol_major(protocol_major);
  message.header.mutable_envelope()->set_sender("coupler");
  auto* apply = message.header.mutable_exchange()->add_operations()->mutable_apply();
  apply->set_region("ghost_cells");
  std::vector<double> rho(cells);
  std::iota(rho.begin(), rho.end(), 1.0);
  add_array(message, {"ghost_cells", "rho", {}, "kg/m^3"}, std::move(rho));
  const std::vector<double> momentum(3 * cells, -2.5);
  add_array(message, {"ghost_cells", "momentum", {cells, 3}, "kg/(m^2*s)"},
            std::span<const double>(momentum));
  return message;
}

std::string error_of(Message&& message) {
  try {
    decode(encode(std::move(message)));
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(Codec, RoundTripKeepsHeaderAndFrameValuesBitForBit) {
  Message decoded = decode(encode(exchange_with_strip(100)));
  ASSERT_TRUE(decoded.header.has_exchange());
  EXPECT_EQ(decoded.header.exchange().operations(0).apply().region(), "ghost_cells");
  const auto rho = view_array<double>(decoded, "ghost_cells", "rho");
  ASSERT_EQ(rho.values().size(), 100U);
  EXPECT_EQ(rho.values()[99], 100.0);
  EXPECT_EQ(rho.descriptor().units(), "kg/m^3");
  const auto momentum = view_array<double>(decoded, "ghost_cells", "momentum");
  EXPECT_EQ(momentum.descriptor().shape(1), 3U);
  EXPECT_EQ(momentum.values()[299], -2.5);
}

TEST(Codec, MajorVersionMismatchIsAClearError) {
  Message message = exchange_with_strip(4);
  message.header.mutable_envelope()->set_protocol_major(2);
  const std::string text = error_of(std::move(message));
  EXPECT_NE(text.find("protocol version mismatch"), std::string::npos) << text;
  EXPECT_NE(text.find("'coupler' speaks v2, this build speaks v1"), std::string::npos) << text;
}

TEST(Codec, FrameWhoseByteLengthDisagreesWithShapeIsRejected) {
  Message message = exchange_with_strip(4);
  message.header.mutable_arrays(1)->set_shape(0, 5);
  const std::string text = error_of(std::move(message));
  EXPECT_NE(text.find("should have 120 bytes"), std::string::npos) << text;
}

TEST(Codec, MissingFrameAndDuplicateFrameIndexAreRejected) {
  Message missing = exchange_with_strip(4);
  missing.frames.pop_back();
  EXPECT_NE(error_of(std::move(missing)).find("describes 2 arrays but carries 1"),
            std::string::npos);
  Message duplicate = exchange_with_strip(4);
  duplicate.header.mutable_arrays(1)->set_frame_index(0);
  EXPECT_NE(error_of(std::move(duplicate)).find("already described"), std::string::npos);
}

TEST(Codec, HeaderWithoutBodyOrEnvelopeIsRejected) {
  Message no_body;
  no_body.header.mutable_envelope()->set_protocol_major(protocol_major);
  EXPECT_NE(error_of(std::move(no_body)).find("has no body"), std::string::npos);
  Message no_envelope;
  no_envelope.header.mutable_ping();
  EXPECT_NE(error_of(std::move(no_envelope)).find("no envelope"), std::string::npos);
}

TEST(Codec, MisalignedFrameIsViewedThroughAnAlignedCopy) {
  Message message = exchange_with_strip(8);
  std::vector<std::byte> storage(8 * sizeof(double) + 1);
  std::memcpy(storage.data() + 1, message.frames[0].data(), 8 * sizeof(double));
  // Wrap the odd address without copying (no free function: `storage` owns it).
  message.frames[0] = zmq::message_t(storage.data() + 1, 8 * sizeof(double), nullptr, nullptr);
  const auto rho = view_array<double>(message, "ghost_cells", "rho");
  EXPECT_TRUE(rho.copied());
  EXPECT_EQ(rho.values()[7], 8.0);
}

TEST(Codec, WrongDtypeOrMissingArrayNamesTheArray) {
  const Message message = decode(encode(exchange_with_strip(2)));
  try {
    view_array<std::uint64_t>(message, "ghost_cells", "rho");
    FAIL() << "dtype mismatch accepted";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("ghost_cells/rho' has dtype DTYPE_F64"),
              std::string::npos);
  }
  EXPECT_THROW(view_array<double>(message, "ghost_cells", "pressure"), Error);
}

}  // namespace
}  // namespace mpfd::cosim
