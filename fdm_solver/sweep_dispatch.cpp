#include "fdm_solver/sweep_kernel.hpp"

namespace mpfd::fdm {

std::optional<BadCell> sweep_block(Pencil& pencil, const BlockTransfer& t, const SweepStep& step,
                                   std::span<const eos::AnyEos> models, EndFluxes& ends,
                                   const CrossingTimeRequest* crossing, double* min_crossing_time) {
#if MPFD_SWEEP_AVX2
  // Measured on the 128^3 blast: 1.5x the baseline's cell-updates/s.
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2)
    return isa_avx2::sweep_block(pencil, t, step, models, ends, crossing, min_crossing_time);
#endif
  return isa_baseline::sweep_block(pencil, t, step, models, ends, crossing, min_crossing_time);
}

}  // namespace mpfd::fdm
