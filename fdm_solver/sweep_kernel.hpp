#pragma once
// One 1D sweep of the split Euler equations over a block of pencils,
// T (2-53)-(2-58):
//  1. pressure and sound speed from the EOS of each cell's material;
//  2. adaptive artificial viscosity, T (2-56)-(2-58), in conservative form:
//       Ubar_i = U_i + D_{i+1/2} - D_{i-1/2},
//       D_{i+1/2} = kappa/2 eta theta_{i+1/2} (U_{i+1} - U_i),
//       theta_{i+1/2} = max(theta_i, theta_{i+1}),  eta = nu (1 - nu), nu = c dt/dx.
//     (2-56) as printed, theta_i (U_{i+1} - 2U_i + U_{i-1}) / 2, does not
//     conserve mass or energy when theta varies; the face form does, and
//     equals it where theta is uniform.
//  3. two-step Richtmyer Lax-Wendroff (METHOD.md §2: (2-51) as printed drops
//     the flux Jacobian), second order in space and time:
//       U_{i+1/2} = (Ubar_i + Ubar_{i+1})/2 - dt/(2dx) (F(Ubar_{i+1}) - F(Ubar_i))
//       U_i^new   = Ubar_i - dt/dx (F(U_{i+1/2}) - F(U_{i-1/2})).
// The stages run in chunks of a few positions, each stage lagging the one it
// reads by its stencil reach, so that a chunk's working set stays in cache;
// the state is read a few positions ahead of the update and written behind
// it. The EOS is resolved once per block when its cells share one material,
// and inlined. No allocation, no I/O, no globals.

#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "common/eos/any_eos.hpp"
#include "fdm_solver/pencil.hpp"
#include "fdm_solver/pencil_io.hpp"

namespace mpfd::fdm {

struct SweepStep {
  double dt;         ///< time step of this sweep [s]
  double dx;         ///< cell size along the sweep [m]
  double viscosity;  ///< kappa, scales eta of T (2-58); 0 switches it off [-]
  int switch_power;  ///< p, the viscosity goes with theta^p of T (2-57); 1...4 [-]
};

/// A cell whose state is not physical (density or pressure not > 0, or not finite).
struct BadCell {
  std::size_t position;  ///< position along the pencil (cell + kGhost)
  std::size_t lane;      ///< lane of the block
  double density;
  double pressure;
};

/// What crossed faces of the sweep during it, per lane and unit face area, in
/// the +axis direction: dt F - dx D (kg/m^2, kg/(m s), J/m^2; pencil variables).
/// Written by the sweep for its block's lanes only (and `tapped` only if a tap
/// is set), so left uninitialised: a block of one x-line would else clear
/// 16 lanes' worth for each line.
struct EndFluxes {
  using Lanes = std::array<std::array<double, 5>, kMaxLanes>;
  Lanes lower;   ///< the face below the first updated cell
  Lanes upper;   ///< the face above the last updated cell
  Lanes tapped;  ///< the face below cell BlockTransfer::tap, if set
};

/// Asks a sweep for the smallest crossing time dx_a / (|u_a| + c) over its
/// updated cells and active axes a, at their new state (the stable dt of the
/// next step, computed while the cells are in cache).
struct CrossingTimeRequest {
  std::array<std::size_t, 3> slot;    ///< pencil slot holding the x, y, z momentum
  std::array<double, 3> inv_spacing;  ///< 1/dx, 1/dy, 1/dz [1/m]
  std::array<bool, 3> active;         ///< axes that count
};

/// The build of the sweep kernel in use: "avx2" or "baseline" (SSE2); set
/// once per process from the CPU, or "baseline" with MPFD_FDM_KERNEL=baseline.
[[nodiscard]] const char* sweep_kernel_name() noexcept;

/// Updates cells [t.first, t.last) of every lane of the block in the state,
/// through the pencil (gathered and scattered a few positions at a time).
/// Returns the first unphysical cell met in [first, last) before its
/// update, if any (cells before it may have been updated: the caller stops).
/// With `crossing` set, `min_crossing_time` is lowered to the smallest
/// crossing time of the updated cells.
std::optional<BadCell> sweep_block(Pencil& pencil, const BlockTransfer& t, const SweepStep& step,
                                   std::span<const eos::AnyEos> models, EndFluxes& ends,
                                   const CrossingTimeRequest* crossing = nullptr,
                                   double* min_crossing_time = nullptr);

/// Two sweeps in a row along one axis over the same lines (the x x of
/// (2-52)): t1 and t2 differ only in the range of updated cells, t2's holding
/// t1's. The lines are gathered and scattered once; ends[0] and ends[1] get
/// what crossed the ends of each sweep's range. The same bits as two
/// sweep_block calls.
std::optional<BadCell> sweep_block_twice(Pencil& pencil, const BlockTransfer& t1,
                                         const BlockTransfer& t2, const SweepStep& step,
                                         std::span<const eos::AnyEos> models,
                                         std::array<EndFluxes, 2>& ends,
                                         const CrossingTimeRequest* crossing = nullptr,
                                         double* min_crossing_time = nullptr);

/// sweep_block and sweep_block_twice built for one instruction set: the
/// x86-64 baseline (SSE2) and, where the compiler targets x86-64, AVX2
/// without FMA (so that both give the same bits). The functions above call
/// the widest one the processor has.
#define MPFD_DECLARE_SWEEP_BLOCK                                                                 \
  std::optional<BadCell> sweep_block(Pencil& pencil, const BlockTransfer& t,                     \
                                     const SweepStep& step, std::span<const eos::AnyEos> models, \
                                     EndFluxes& ends, const CrossingTimeRequest* crossing,       \
                                     double* min_crossing_time);                                 \
  std::optional<BadCell> sweep_block_twice(                                                      \
      Pencil& pencil, const BlockTransfer& t1, const BlockTransfer& t2, const SweepStep& step,   \
      std::span<const eos::AnyEos> models, std::array<EndFluxes, 2>& ends,                       \
      const CrossingTimeRequest* crossing, double* min_crossing_time);
namespace isa_baseline {
MPFD_DECLARE_SWEEP_BLOCK
}
namespace isa_avx2 {
MPFD_DECLARE_SWEEP_BLOCK
}
#undef MPFD_DECLARE_SWEEP_BLOCK

}  // namespace mpfd::fdm
