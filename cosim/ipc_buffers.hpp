#pragma once
// Kernel buffers of the AF_UNIX sockets behind an ipc:// endpoint. libzmq 4.3
// applies ZMQ_SNDBUF / ZMQ_RCVBUF to tcp connections only: an ipc connection
// keeps the system default (net.core.wmem_default, 208 KiB on Debian), and a
// V6 reply of 168 kB then crosses in several write/wake rounds between the
// two processes' I/O threads (docs/coupler.md, "Where the ipc share goes").

#include <string>
#include <vector>

namespace mpfd::cosim {

/// Sets SO_SNDBUF and SO_RCVBUF to `bytes` on each of this process's connected
/// AF_UNIX stream sockets whose own or peer address is `path` (an ipc endpoint's
/// address: a file path, or "@name" for the abstract namespace), i.e. the
/// connections ZeroMQ holds for it. The kernel caps the request at
/// net.core.wmem_max / rmem_max; `bytes` <= 0 keeps the default. Returns how
/// many sockets it set; 0 off Linux.
int set_ipc_socket_buffers(const std::string& path, int bytes);

/// SO_SNDBUF of each such socket as the kernel holds it (twice the request).
[[nodiscard]] std::vector<int> ipc_send_buffers(const std::string& path);

}  // namespace mpfd::cosim
