#include "fdm_solver/pencil_io.hpp"

#include <algorithm>

namespace mpfd::fdm {
namespace {

/// State variable held in pencil slot s for a sweep along `axis`.
constexpr std::size_t kSlot[3][5] = {
    {kDensity, kMomentumX, kMomentumY, kMomentumZ, kEnergy},
    {kDensity, kMomentumY, kMomentumZ, kMomentumX, kEnergy},
    {kDensity, kMomentumZ, kMomentumX, kMomentumY, kEnergy},
};

/// Copies cells [lo, hi) of every lane of the block from `src` (the state
/// array at the block's start) into the pencil buffer `dst`. Contiguous runs
/// (lanes adjacent in memory, or a single x-line) are copied as runs.
template <class T>
void copy_in(const T* src, const PencilBlock& block, std::size_t lo, std::size_t hi, T* dst) {
  const std::size_t lanes = block.lanes;
  if (lanes == 1 && block.stride == 1) {
    std::copy(src + lo, src + hi, dst + lo + kGhost);
    return;
  }
  if (lanes == kMaxLanes && block.lane_stride == 1) {  // a full block: fixed-size moves
    for (std::size_t i = lo; i < hi; ++i)
      for (std::size_t w = 0; w < kMaxLanes; ++w)
        dst[(i + kGhost) * kMaxLanes + w] = src[i * block.stride + w];
    return;
  }
  for (std::size_t i = lo; i < hi; ++i)
    for (std::size_t w = 0; w < lanes; ++w)
      dst[(i + kGhost) * lanes + w] = src[i * block.stride + w * block.lane_stride];
}

/// The inverse of copy_in for cells [lo, hi).
void copy_out(const double* src, const PencilBlock& block, std::size_t lo, std::size_t hi,
              double* dst) {
  const std::size_t lanes = block.lanes;
  if (lanes == 1 && block.stride == 1) {
    std::copy(src + lo + kGhost, src + hi + kGhost, dst + lo);
    return;
  }
  if (lanes == kMaxLanes && block.lane_stride == 1) {  // a full block: fixed-size moves
    for (std::size_t i = lo; i < hi; ++i)
      for (std::size_t w = 0; w < kMaxLanes; ++w)
        dst[i * block.stride + w] = src[(i + kGhost) * kMaxLanes + w];
    return;
  }
  for (std::size_t i = lo; i < hi; ++i)
    for (std::size_t w = 0; w < lanes; ++w)
      dst[i * block.stride + w * block.lane_stride] = src[(i + kGhost) * lanes + w];
}

bool is_mirror(config::BoundaryKind kind) {
  return kind != config::BoundaryKind::outflow;
}

/// Fills ghost position `ghost` of every lane from position `source`,
/// reversing the normal momentum for a mirror.
void make_ghost(Pencil& p, std::size_t lanes, std::size_t ghost, std::size_t source, bool mirror) {
  for (std::size_t w = 0; w < lanes; ++w) {
    const std::size_t to = ghost * lanes + w, from = source * lanes + w;
    for (std::size_t s = 0; s < 5; ++s) p.u[s][to] = p.u[s][from];
    if (mirror) p.u[kMn][to] = -p.u[kMn][from];
    p.material[to] = p.material[from];
    p.mix_gamma[to] = p.mix_gamma[from];
    p.mix_pinf[to] = p.mix_pinf[from];
  }
}

}  // namespace

void gather(const EulerState& state, const PencilBlock& block, AxisBoundaries faces,
            std::size_t first, std::size_t last, Pencil& pencil) {
  const std::size_t lanes = block.lanes;
  // Interior cells that exist within the stencil of [first, last).
  const std::size_t lo = first >= kGhost ? first - kGhost : 0;
  const std::size_t hi = std::min(last + kGhost, block.length);
  for (std::size_t s = 0; s < 5; ++s)
    copy_in(state.u[kSlot[block.axis][s]].data() + block.start, block, lo, hi, pencil.u[s].data());
  copy_in(state.material.data() + block.start, block, lo, hi, pencil.material.data());
  if (!state.mix_gamma.empty()) {
    copy_in(state.mix_gamma.data() + block.start, block, lo, hi, pencil.mix_gamma.data());
    copy_in(state.mix_pinf.data() + block.start, block, lo, hi, pencil.mix_pinf.data());
  }

  // Ghosts where the stencil passes a domain face.
  const std::size_t deepest = block.length - 1;  // mirrors of short lines repeat the far end
  if (first < kGhost) {
    const bool mirror = is_mirror(faces.lower);
    for (std::size_t m = 0; m < kGhost; ++m)
      make_ghost(pencil, lanes, kGhost - 1 - m, mirror ? kGhost + std::min(m, deepest) : kGhost,
                 mirror);
  }
  if (last + kGhost > block.length) {
    const bool mirror = is_mirror(faces.upper);
    const std::size_t end = block.length + kGhost;  // first ghost past the upper face
    for (std::size_t m = 0; m < kGhost; ++m)
      make_ghost(pencil, lanes, end + m, mirror ? end - 1 - std::min(m, deepest) : end - 1, mirror);
  }
}

void scatter(const Pencil& pencil, const PencilBlock& block, std::size_t first, std::size_t last,
             EulerState& state) {
  for (std::size_t s = 0; s < 5; ++s)
    copy_out(pencil.u[s].data(), block, first, last,
             state.u[kSlot[block.axis][s]].data() + block.start);
}

}  // namespace mpfd::fdm
