#pragma once
// Keeps the memory of large message frames in the process heap. By default
// glibc serves every block over 128 kB (up to a moving threshold) with a
// fresh mmap, so each multi-megabyte frame of a field handoff or a wide strip
// is mapped, page-faulted in, cleared by the kernel and unmapped again:
// measured on this project's 2-core machine, 8 MB steps ran at 0.94 GB/s each
// way with that, and 1.59 GB/s with the blocks kept in the heap (bare ZeroMQ
// in the same process: 1.82 GB/s). Process-wide, so it is applied once, by the
// first Hub or Participant; a process that must not have it can call nothing
// else of cosim/.

namespace mpfd::cosim {

/// Raises glibc's mmap and trim thresholds (to 128 MiB and 256 MiB) once per
/// process. Has no effect on other C libraries.
void keep_large_frames_in_heap();

}  // namespace mpfd::cosim
