#pragma once
// The MPM background grid, stored sparsely: nodes live in blocks of 4 nodes
// per active axis (4, 16 or 64 nodes), and only blocks that some particle's
// stencil reaches exist in a step. The grid is rebuilt every step (T §2.1.1:
// the deformed grid is discarded); after the first steps the arrays have
// reached their largest size and a rebuild allocates nothing.
//
// Node coordinates here are "storage" coordinates: grid node index + 1 on an
// active axis, so the ghost layer a GIMP particle next to a face reaches
// (node -1 or nx + 1) has a place; an inactive axis has the single index 0.
//
// Particles are also binned here by their home block (the block of their
// stencil's first node). A stencil spans at most two blocks per axis, so home
// blocks whose coordinates have the same parities never share a node: the
// 2^d parity colours let particle-to-grid scatters run in parallel, one block
// per thread at a time, without atomics.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "common/grid/uniform_grid.hpp"

namespace mpfd::mpm {

class SparseGrid {
 public:
  static constexpr int kBlockShift = 2;  // 4 nodes per active axis
  static constexpr int kColours = 8;

  explicit SparseGrid(const grid::UniformGrid& grid);

  [[nodiscard]] const grid::UniformGrid& grid() const { return grid_; }
  /// Storage offset of grid node indices on each axis (1 active, 0 inactive).
  [[nodiscard]] const grid::Index3& offset() const { return offset_; }

  /// Forgets last step's blocks (only those are touched).
  void clear();
  /// Makes the blocks holding the storage-coordinate node box [lo, hi] exist;
  /// returns the slot of lo's block (the particle's home block).
  std::int32_t activate(const grid::Index3& lo, const grid::Index3& hi);
  /// Sizes (grows only) and zeroes the node arrays for the blocks activated.
  void allocate_nodes();
  /// Sorts particles by home block into buckets and the buckets by colour.
  void bin_particles(std::span<const std::int32_t> home_slot);

  /// Index into the node arrays of a storage-coordinate node of an active block.
  [[nodiscard]] std::size_t node(int i, int j, int k) const {
    const std::int32_t slot = table_[block_id(i >> shift_[0], j >> shift_[1], k >> shift_[2])];
    return static_cast<std::size_t>(slot) * block_nodes_ +
           static_cast<std::size_t>(
               (i & mask_[0]) + block_dim_[0] * ((j & mask_[1]) + block_dim_[1] * (k & mask_[2])));
  }
  /// Like node(), for any storage coordinate: -1 when its block is not active
  /// (or lies outside the grid's ghost layer).
  [[nodiscard]] std::ptrdiff_t find_node(const grid::Index3& storage) const;
  /// Slot of the active block with block coordinates (bi, bj, bk).
  [[nodiscard]] std::int32_t slot(int bi, int bj, int bk) const {
    return table_[block_id(bi, bj, bk)];
  }
  /// Storage coordinates of node `n` of the arrays (for boundaries and output).
  [[nodiscard]] grid::Index3 node_coordinates(std::size_t n) const;

  [[nodiscard]] std::size_t block_count() const { return active_.size(); }
  [[nodiscard]] std::size_t block_nodes() const { return block_nodes_; }
  [[nodiscard]] std::size_t node_count() const { return active_.size() * block_nodes_; }

  /// Home-block slots of one colour, and the particles whose home is a slot.
  [[nodiscard]] std::span<const std::int32_t> colour(int c) const {
    return {colour_slots_.data() + colour_begin_[c], colour_slots_.data() + colour_begin_[c + 1]};
  }
  [[nodiscard]] std::span<const std::int32_t> bucket(std::int32_t slot) const {
    return {order_.data() + bucket_begin_[slot], order_.data() + bucket_begin_[slot + 1]};
  }

  // Node arrays (size node_count()), SoA.
  std::vector<double> mass;                     ///< m_I (2-12) [kg]
  std::array<std::vector<double>, 3> momentum;  ///< p_I (2-9), then p_I^{n+1} (2-13) [kg m/s]
  std::array<std::vector<double>, 3> force;     ///< f_I (2-14) [N]
  std::array<std::vector<double>, 3> remapped;  ///< sum m_p N v_p^{n+1} (2-17) [kg m/s]

 private:
  [[nodiscard]] std::size_t block_id(int bi, int bj, int bk) const {
    return static_cast<std::size_t>(bi) +
           static_cast<std::size_t>(blocks_[0]) *
               (static_cast<std::size_t>(bj) + static_cast<std::size_t>(blocks_[1]) * bk);
  }

  grid::UniformGrid grid_;
  grid::Index3 offset_{};
  grid::Index3 shift_{};
  grid::Index3 mask_{};
  grid::Index3 block_dim_{};
  grid::Index3 blocks_{};
  std::size_t block_nodes_ = 1;
  std::vector<std::int32_t> table_;   // block id -> slot, -1 when absent
  std::vector<std::int32_t> active_;  // slot -> block id
  std::vector<std::int32_t> bucket_begin_;
  std::vector<std::int32_t> order_;  // particle indices sorted by home slot
  std::vector<std::int32_t> colour_slots_;
  std::array<std::int32_t, kColours + 1> colour_begin_{};
};

}  // namespace mpfd::mpm
