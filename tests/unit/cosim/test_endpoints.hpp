#pragma once
// Bind endpoints for tests: a unique name per call, ipc sockets under the temp dir.

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

#include "cosim/endpoint.hpp"

namespace mpfd::cosim::testing {

inline std::string unique_bind_endpoint(Transport transport) {
  static std::atomic<int> counter{0};
  const std::string tag = std::to_string(::getpid()) + "-" + std::to_string(counter++);
  switch (transport) {
    case Transport::inproc:
      return "inproc://cosim-test-" + tag;
    case Transport::ipc:
      return "ipc://" + (std::filesystem::temp_directory_path() / ("mpfd-cosim-" + tag)).string();
    case Transport::tcp:
      return "tcp://127.0.0.1:*";
  }
  return {};
}

/// Names parameterized tests after their transport ("inproc", "ipc", "tcp").
inline std::string transport_test_name(const ::testing::TestParamInfo<Transport>& param) {
  return std::string(transport_name(param.param));
}

}  // namespace mpfd::cosim::testing
