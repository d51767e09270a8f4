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

/// Fills ghost position `ghost` of every lane of `u` from position `source`,
/// reversing the normal momentum for a mirror.
void make_ghost_state(Pencil& p, std::size_t lanes, std::size_t ghost, std::size_t source,
                      bool mirror) {
  for (std::size_t w = 0; w < lanes; ++w) {
    const std::size_t to = ghost * lanes + w, from = source * lanes + w;
    for (std::size_t s = 0; s < 5; ++s) p.u[s][to] = p.u[s][from];
    if (mirror) p.u[kMn][to] = -p.u[kMn][from];
  }
}

/// The same for the material and a mixed cell's EOS.
void make_ghost_material(Pencil& p, std::size_t lanes, std::size_t ghost, std::size_t source) {
  for (std::size_t w = 0; w < lanes; ++w) {
    const std::size_t to = ghost * lanes + w, from = source * lanes + w;
    p.material[to] = p.material[from];
    p.mix_gamma[to] = p.mix_gamma[from];
    p.mix_pinf[to] = p.mix_pinf[from];
  }
}

/// Calls make(ghost, source, mirror) for every ghost of the lower face.
template <class Make>
void lower_ghosts(const BlockTransfer& t, const Make& make) {
  const std::size_t deepest = t.block.length - 1;  // mirrors of short lines repeat the far end
  const bool mirror = is_mirror(t.faces.lower);
  for (std::size_t m = 0; m < kGhost; ++m)
    make(kGhost - 1 - m, mirror ? kGhost + std::min(m, deepest) : kGhost, mirror);
}

/// Calls make(ghost, source, mirror) for every ghost of the upper face.
template <class Make>
void upper_ghosts(const BlockTransfer& t, const Make& make) {
  const std::size_t deepest = t.block.length - 1;
  const bool mirror = is_mirror(t.faces.upper);
  const std::size_t end = t.block.length + kGhost;  // first ghost past the upper face
  for (std::size_t m = 0; m < kGhost; ++m)
    make(end + m, mirror ? end - 1 - std::min(m, deepest) : end - 1, mirror);
}

bool needs_lower_ghosts(const BlockTransfer& t) {
  return t.first < kGhost;
}
bool needs_upper_ghosts(const BlockTransfer& t) {
  return t.last + kGhost > t.block.length;
}

}  // namespace

void gather_materials(const BlockTransfer& t, Pencil& pencil) {
  const EulerState& state = t.state;
  const PencilBlock& block = t.block;
  // Interior cells that exist within the stencil of [first, last).
  const std::size_t lo = t.first >= kGhost ? t.first - kGhost : 0;
  const std::size_t hi = std::min(t.last + kGhost, block.length);
  copy_in(state.material.data() + block.start, block, lo, hi, pencil.material.data());
  if (!state.mix_gamma.empty()) {
    copy_in(state.mix_gamma.data() + block.start, block, lo, hi, pencil.mix_gamma.data());
    copy_in(state.mix_pinf.data() + block.start, block, lo, hi, pencil.mix_pinf.data());
  }
  const auto make = [&](std::size_t ghost, std::size_t source, bool) {
    make_ghost_material(pencil, block.lanes, ghost, source);
  };
  if (needs_lower_ghosts(t)) lower_ghosts(t, make);
  if (needs_upper_ghosts(t)) upper_ghosts(t, make);
}

void gather_rows(const BlockTransfer& t, std::size_t from, std::size_t to, Pencil& pencil) {
  const PencilBlock& block = t.block;
  // Interior cells of the range (pencil position = cell + kGhost).
  const std::size_t lo = std::max(from, kGhost) - kGhost;
  const std::size_t hi = std::min(to, block.length + kGhost) - kGhost;
  if (lo < hi)
    for (std::size_t s = 0; s < 5; ++s)
      copy_in(t.state.u[kSlot[block.axis][s]].data() + block.start, block, lo, hi,
              pencil.u[s].data());
  const auto make = [&](std::size_t ghost, std::size_t source, bool mirror) {
    make_ghost_state(pencil, block.lanes, ghost, source, mirror);
  };
  // The first range reaches past the cells the lower ghosts mirror; the one
  // that first passes the upper face holds those the upper ghosts mirror.
  if (from < kGhost) lower_ghosts(t, make);
  if (from <= block.length + kGhost && to > block.length + kGhost) upper_ghosts(t, make);
}

void remake_ghosts(const BlockTransfer& t, Pencil& pencil) {
  const auto make = [&](std::size_t ghost, std::size_t source, bool mirror) {
    make_ghost_state(pencil, t.block.lanes, ghost, source, mirror);
  };
  if (needs_lower_ghosts(t)) lower_ghosts(t, make);
  if (needs_upper_ghosts(t)) upper_ghosts(t, make);
}

void scatter_rows(const Pencil& pencil, const BlockTransfer& t, std::size_t from, std::size_t to) {
  for (std::size_t s = 0; s < 5; ++s)
    copy_out(pencil.u_new[s].data(), t.block, from - kGhost, to - kGhost,
             t.state.u[kSlot[t.block.axis][s]].data() + t.block.start);
}

}  // namespace mpfd::fdm
