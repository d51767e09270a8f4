#include "cosim/large_frames.hpp"

#include <malloc.h>

#include <mutex>

namespace mpfd::cosim {

void keep_large_frames_in_heap() {
  static std::once_flag once;
  std::call_once(once, [] {
#ifdef M_MMAP_THRESHOLD
    mallopt(M_MMAP_THRESHOLD, 128 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
  });
}

}  // namespace mpfd::cosim
