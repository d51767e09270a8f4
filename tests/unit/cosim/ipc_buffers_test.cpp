// cosim/ipc_buffers: the Hub and the Participant size the kernel buffers of an
// ipc connection themselves (libzmq applies ZMQ_SNDBUF / ZMQ_RCVBUF to tcp only).
#include "cosim/ipc_buffers.hpp"

#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <fstream>

#include "cosim/endpoint.hpp"
#include "cosim/hub.hpp"
#include "echo_solver.hpp"
#include "test_endpoints.hpp"

namespace mpfd::cosim {
namespace {

/// The value of a sysctl file; 0 where it cannot be read (a network namespace may lack it).
int sysctl_value(const char* file) {
  std::ifstream in(file);
  int value = 0;
  in >> value;
  return value;
}

/// SO_SNDBUF of a fresh AF_UNIX stream socket: what a connection starts with.
int default_send_buffer() {
  int pair[2];
  if (socketpair(AF_UNIX, SOCK_STREAM, 0, pair) != 0) return 0;
  int bytes = 0;
  socklen_t size = sizeof bytes;
  getsockopt(pair[0], SOL_SOCKET, SO_SNDBUF, &bytes, &size);
  close(pair[0]);
  close(pair[1]);
  return bytes;
}

TEST(IpcBuffers, BothEndsOfAnIpcConnectionGetTheConfiguredBuffers) {
#ifndef __linux__
  GTEST_SKIP() << "ipc socket buffers are set on Linux only";
#endif
  TransportOptions options;
  options.reply_timeout = std::chrono::milliseconds{3000};
  options.idle_timeout = std::chrono::milliseconds{3000};
  zmq::context_t context;
  Hub hub(context, testing::unique_bind_endpoint(Transport::ipc), options);
  const std::string path = parse_endpoint(hub.endpoint()).address;
  std::atomic<bool> connected{false};
  testing::SolverThread solver([&] {
    Participant participant(context, hub.endpoint(), "fdm", options);
    participant.connect({});
    connected = true;
    testing::serve_echo(participant);
  });
  const std::vector<std::string> peers{"fdm"};
  hub.accept(peers, "run-ipc-buffers");
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(3);
  while (!connected && std::chrono::steady_clock::now() < deadline) std::this_thread::yield();
  ASSERT_TRUE(connected) << "the solver thread did not get its HelloAck";

  // Linux doubles a request it caps at net.core.wmem_max (Debian: 212992, the
  // default a connection starts with), so even capped the buffer grows.
  const int start = default_send_buffer();
  ASSERT_GT(start, 0);
  const std::vector<int> sizes = ipc_send_buffers(path);
  ASSERT_EQ(sizes.size(), 2U) << "the coupler's accepted socket and the solver's connected one";
  const int wmem_max = sysctl_value("/proc/sys/net/core/wmem_max");
  for (const int size : sizes) {
    EXPECT_GT(size, start);
    if (wmem_max > 0) {
      EXPECT_EQ(size, 2 * std::min(options.socket_buffer_bytes, wmem_max));
    }
  }

  Message shutdown;
  shutdown.header.mutable_shutdown();
  hub.send("fdm", std::move(shutdown));
  (void)hub.receive_from("fdm");
}

TEST(IpcBuffers, AnAddressNoSocketHoldsSetsNone) {
  EXPECT_EQ(set_ipc_socket_buffers("/nonexistent/mpfd-ipc-buffers", 1 << 20), 0);
  EXPECT_TRUE(ipc_send_buffers("@mpfd-no-such-abstract-socket").empty());
}

}  // namespace
}  // namespace mpfd::cosim
