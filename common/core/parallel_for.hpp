#pragma once
// Threading of loops over cells, particles and tracers (OpenMP, static
// schedule). A body is a point kernel: it writes only its own entry.

#include <cstddef>

namespace mpfd {

/// Below this many iterations a loop runs on one thread: starting a team
/// costs more than it saves, and on a loaded machine a descheduled thread
/// stalls the barrier for a whole time slice (measured: a 16k-tracer loop at
/// 4096 spent 95 % of its time in the OpenMP barrier).
inline constexpr std::ptrdiff_t kMinParallelCount = 32768;

/// Runs body(i) for i in [0, n).
template <class Body>
void parallel_for(std::size_t n, const Body& body) {
  const auto count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel for schedule(static) if (count >= kMinParallelCount)
  for (std::ptrdiff_t i = 0; i < count; ++i) body(static_cast<std::size_t>(i));
}

/// Runs body(i) for i in [0, n) and returns the sum of what it returns
/// (e.g. 1 for each entry it flags).
template <class Body>
std::size_t parallel_sum(std::size_t n, const Body& body) {
  const auto count = static_cast<std::ptrdiff_t>(n);
  std::size_t total = 0;
#pragma omp parallel for schedule(static) reduction(+ : total) if (count >= kMinParallelCount)
  for (std::ptrdiff_t i = 0; i < count; ++i) total += body(static_cast<std::size_t>(i));
  return total;
}

}  // namespace mpfd
