#include "cosim/endpoint.hpp"

#include <gtest/gtest.h>

#include "common/core/error.hpp"

namespace mpfd::cosim {
namespace {

std::string error_of(std::string_view text) {
  try {
    parse_endpoint(text);
  } catch (const Error& error) {
    return error.what();
  }
  return "no error";
}

TEST(Endpoint, ParsesEachTransport) {
  EXPECT_EQ(parse_endpoint("inproc://solvers").transport, Transport::inproc);
  EXPECT_EQ(parse_endpoint("ipc:///tmp/mpfd.sock").address, "/tmp/mpfd.sock");
  const auto tcp = parse_endpoint("tcp://10.0.0.2:5555");
  EXPECT_EQ(tcp.transport, Transport::tcp);
  EXPECT_EQ(tcp.text, "tcp://10.0.0.2:5555");
  EXPECT_EQ(parse_endpoint("tcp://*:*").transport, Transport::tcp);
}

TEST(Endpoint, TcpWithoutPortNamesTheStringAndTheExpectedForm) {
  const std::string message = error_of("tcp://host");
  EXPECT_NE(message.find("'tcp://host'"), std::string::npos) << message;
  EXPECT_NE(message.find("tcp://<host>:<port>"), std::string::npos) << message;
}

TEST(Endpoint, RejectsBadPortsSchemesAndEmptyAddresses) {
  EXPECT_NE(error_of("tcp://host:70000").find("1..65535"), std::string::npos);
  EXPECT_NE(error_of("tcp://host:abc").find("'abc'"), std::string::npos);
  EXPECT_NE(error_of("udp://host:1").find("unknown scheme 'udp'"), std::string::npos);
  EXPECT_NE(error_of("inproc://").find("empty address"), std::string::npos);
  EXPECT_NE(error_of("localhost:5555").find("no scheme"), std::string::npos);
}

}  // namespace
}  // namespace mpfd::cosim
