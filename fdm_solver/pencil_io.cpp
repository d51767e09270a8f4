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

bool is_mirror(config::BoundaryKind kind) {
  return kind != config::BoundaryKind::outflow;
}

/// Fills ghost position `ghost` of the pencil from interior cell `source`
/// (pencil positions), reversing the normal momentum for a mirror.
void make_ghost(Pencil& p, std::size_t ghost, std::size_t source, bool mirror) {
  for (std::size_t s = 0; s < 5; ++s) p.u[s][ghost] = p.u[s][source];
  if (mirror) p.u[kMn][ghost] = -p.u[kMn][source];
  p.material[ghost] = p.material[source];
}

}  // namespace

void gather(const EulerState& state, const PencilLine& line, AxisBoundaries faces,
            std::size_t first, std::size_t last, Pencil& pencil) {
  // Interior cells that exist within the stencil of [first, last).
  const std::size_t lo = first >= kGhost ? first - kGhost : 0;
  const std::size_t hi = std::min(last + kGhost, line.length);
  for (std::size_t s = 0; s < 5; ++s) {
    const double* src = state.u[kSlot[line.axis][s]].data() + line.start;
    double* dst = pencil.u[s].data() + kGhost;
    for (std::size_t i = lo; i < hi; ++i) dst[i] = src[i * line.stride];
  }
  const std::uint8_t* mat = state.material.data() + line.start;
  for (std::size_t i = lo; i < hi; ++i) pencil.material[i + kGhost] = mat[i * line.stride];

  // Ghosts where the stencil passes a domain face.
  if (first < kGhost) {
    for (std::size_t m = 0; m < kGhost; ++m) {
      const std::size_t source =
          is_mirror(faces.lower) ? kGhost + std::min(m, line.length - 1) : kGhost;
      make_ghost(pencil, kGhost - 1 - m, source, is_mirror(faces.lower));
    }
  }
  if (last + kGhost > line.length) {
    const std::size_t end = line.length + kGhost;  // first ghost past the upper face
    for (std::size_t m = 0; m < kGhost; ++m) {
      const std::size_t source =
          is_mirror(faces.upper) ? end - 1 - std::min(m, line.length - 1) : end - 1;
      make_ghost(pencil, end + m, source, is_mirror(faces.upper));
    }
  }
}

void scatter(const Pencil& pencil, const PencilLine& line, std::size_t first, std::size_t last,
             EulerState& state) {
  for (std::size_t s = 0; s < 5; ++s) {
    double* dst = state.u[kSlot[line.axis][s]].data() + line.start;
    const double* src = pencil.u[s].data() + kGhost;
    for (std::size_t i = first; i < last; ++i) dst[i * line.stride] = src[i];
  }
}

}  // namespace mpfd::fdm
