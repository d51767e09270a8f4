#pragma once
// Threading of the tracer module's loops over tracers and cells (OpenMP,
// static schedule). A body is a point kernel: it writes only its own entry.
// Candidate for common/core once the rest of fdm_solver/ needs the same.

#include <cstddef>

namespace mpfd::fdm {

/// Below this many iterations a loop runs on one thread: forking and joining
/// would cost more than the work (and stalls on a loaded machine).
inline constexpr std::ptrdiff_t kMinParallelCount = 4096;

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

}  // namespace mpfd::fdm
