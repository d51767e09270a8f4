#include <sys/resource.h>

#include "common/io/standalone_loop.hpp"

namespace mpfd::io {

long long peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024LL * usage.ru_maxrss;  // Linux reports kilobytes
}

}  // namespace mpfd::io
