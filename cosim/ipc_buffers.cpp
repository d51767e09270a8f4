#include "cosim/ipc_buffers.hpp"

#include <charconv>
#include <cstddef>
#include <cstring>
#include <filesystem>

#ifdef __linux__
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#endif

namespace mpfd::cosim {
namespace {

#ifdef __linux__
/// Whether the address of a socket (getsockname or getpeername) is `path`.
template <class Query>
bool address_is(int fd, const std::string& path, Query query) {
  sockaddr_un address{};
  socklen_t length = sizeof address;
  if (query(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) return false;
  if (address.sun_family != AF_UNIX || length <= offsetof(sockaddr_un, sun_path)) return false;
  const std::size_t size = length - offsetof(sockaddr_un, sun_path);
  if (address.sun_path[0] == '\0')  // abstract: "@name", not NUL-terminated
    return !path.empty() && path[0] == '@' &&
           std::string(address.sun_path + 1, size - 1) == path.substr(1);
  return std::string(address.sun_path, strnlen(address.sun_path, size)) == path;
}

/// The fds of this process's connected AF_UNIX stream sockets at `path` (not the listener).
std::vector<int> ipc_sockets(const std::string& path) {
  std::vector<int> found;
  std::error_code error;
  for (std::filesystem::directory_iterator it("/proc/self/fd", error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    int fd = -1;
    if (std::from_chars(name.data(), name.data() + name.size(), fd).ec != std::errc{}) continue;
    struct stat status {};
    if (fstat(fd, &status) != 0 || !S_ISSOCK(status.st_mode)) continue;
    int domain = 0, type = 0;
    socklen_t size = sizeof domain;
    if (getsockopt(fd, SOL_SOCKET, SO_DOMAIN, &domain, &size) != 0 || domain != AF_UNIX) continue;
    size = sizeof type;
    if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &size) != 0 || type != SOCK_STREAM) continue;
    int listening = 0;
    size = sizeof listening;
    if (getsockopt(fd, SOL_SOCKET, SO_ACCEPTCONN, &listening, &size) != 0 || listening) continue;
    if (address_is(fd, path, getpeername) || address_is(fd, path, getsockname)) found.push_back(fd);
  }
  return found;
}
#endif

}  // namespace

int set_ipc_socket_buffers(const std::string& path, int bytes) {
  int count = 0;
  if (bytes <= 0) return count;  // TransportOptions: 0 keeps the OS default
#ifdef __linux__
  for (const int fd : ipc_sockets(path)) {
    const bool sent = setsockopt(fd, SOL_SOCKET, SO_SNDBUF, &bytes, sizeof bytes) == 0;
    const bool received = setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &bytes, sizeof bytes) == 0;
    count += sent && received ? 1 : 0;
  }
#else
  (void)path;
  (void)bytes;
#endif
  return count;
}

std::vector<int> ipc_send_buffers(const std::string& path) {
  std::vector<int> sizes;
#ifdef __linux__
  for (const int fd : ipc_sockets(path)) {
    int bytes = 0;
    socklen_t size = sizeof bytes;
    if (getsockopt(fd, SOL_SOCKET, SO_SNDBUF, &bytes, &size) == 0) sizes.push_back(bytes);
  }
#else
  (void)path;
#endif
  return sizes;
}

}  // namespace mpfd::cosim
