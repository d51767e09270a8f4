// The next step's particle-to-grid map, made early for a coupler
// (MpmSolver::map_next_step, mpm_solver.hpp). A coupled step exports the MPM's
// ghost nodes after its advance (T §4.3 step 4 of the next step needs them
// before the FDM advances); their values are the next step's (2-9), (2-12) of
// the same particles. Mapping the whole grid then, and letting the advance
// start from that map, makes the export a copy instead of a second scatter.
#include <algorithm>
#include <string>

#include "common/core/error.hpp"
#include "mpm_solver/mpm_solver.hpp"

namespace mpfd::mpm {

void MpmSolver::map_next_step(const grid::Index3& lo, const grid::Index3& hi) {
  for (int a = 0; a < 3; ++a)
    if (!(lo[a] < hi[a]))
      throw Error("mpm: map_next_step needs a box with lo < hi on every axis, got axis " +
                  std::to_string(a) + ": [" + std::to_string(lo[a]) + ", " + std::to_string(hi[a]) +
                  ")");
  rebuild_grid();
  if (contact_) mark_shared_nodes();
  for (int a = 0; a < 3; ++a) {
    next_map_.lo[a] = lo[a] + grid_.offset()[a];
    next_map_.hi[a] = hi[a] + grid_.offset()[a];
  }
  next_map_energy_.assign(grid_.node_count(), 0.0);  // grow-only once warm
  next_map_.valid = true;
  next_map_.appended = 0;
  particles_to_grid(first_scatter());
}

bool MpmSolver::next_step_mapped(const grid::Index3& lo, const grid::Index3& hi) const {
  if (!next_map_.valid) return false;
  for (int a = 0; a < 3; ++a)
    if (next_map_.lo[a] != lo[a] + grid_.offset()[a] ||
        next_map_.hi[a] != hi[a] + grid_.offset()[a])
      return false;
  return true;
}

std::optional<std::array<grid::Index3, 2>> MpmSolver::next_step_map_for_checkpoint() {
  if (next_map_.valid && next_map_.appended > 0) next_map_.valid = false;
  if (!next_map_.valid) return std::nullopt;
  std::array<grid::Index3, 2> box{};
  for (int a = 0; a < 3; ++a) {
    box[0][a] = next_map_.lo[a] - grid_.offset()[a];
    box[1][a] = next_map_.hi[a] - grid_.offset()[a];
  }
  return box;
}

void MpmSolver::read_next_step_box(const grid::Index3& lo, const grid::Index3& hi,
                                   NodeBoxMap& out) const {
  if (!next_step_mapped(lo, hi))
    throw Error("mpm: read_next_step_box on a box map_next_step did not map (or the map is gone)");
  out.reset(lo, hi);
  std::size_t n = 0;
  for (int i = lo[0]; i < hi[0]; ++i)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int k = lo[2]; k < hi[2]; ++k, ++n) {
        const std::ptrdiff_t at =
            grid_.find_node({i + grid_.offset()[0], j + grid_.offset()[1], k + grid_.offset()[2]});
        if (at < 0) continue;  // no particle reaches it: zero, as the box map gives
        const auto node = static_cast<std::size_t>(at);
        out.mass[n] = grid_.mass[node];
        for (int a = 0; a < 3; ++a)
          out.momentum[3 * n + static_cast<std::size_t>(a)] =
              grid_.momentum[static_cast<std::size_t>(a)][node];
        out.internal_energy[n] = next_map_energy_[node];
      }
}

void MpmSolver::add_to_next_step_map(std::size_t first) {
  if (!next_map_.valid) return;
  const std::size_t n = particles_.size();
  home_slot_.resize(n);
  for (std::size_t p = first; p < n; ++p) {
    grid::Index3 lo{}, hi{};
    stencil_box(p, lo, hi);
    // A stencil spans at most two blocks per axis: those of its corners.
    for (int corner = 0; corner < 8; ++corner) {
      const grid::Index3 at{(corner & 1) ? hi[0] : lo[0], (corner & 2) ? hi[1] : lo[1],
                            (corner & 4) ? hi[2] : lo[2]};
      if (grid_.find_node(at) < 0) {  // a block the map lacks: the advance maps afresh
        next_map_.valid = false;
        return;
      }
    }
    // Corner 0 is the home node: its block is the particle's home block.
    home_slot_[p] = static_cast<std::int32_t>(static_cast<std::size_t>(grid_.find_node(lo)) /
                                              grid_.block_nodes());
  }
  // The later passes of the step visit particles through the bins; a bucket
  // keeps index order, so the appended particles come last in theirs.
  grid_.bin_particles(home_slot_);
  scatter_particles(first_scatter(), ScatterOrder::appended, first);
  next_map_.appended += n - first;
}

bool MpmSolver::loads_on_mapped_blocks() const {
  return std::all_of(node_loads_.begin(), node_loads_.end(), [&](const NodeLoad& load) {
    return grid_.find_node({load.node[0] + grid_.offset()[0], load.node[1] + grid_.offset()[1],
                            load.node[2] + grid_.offset()[2]}) >= 0;
  });
}

}  // namespace mpfd::mpm
