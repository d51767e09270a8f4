#include "mpm_solver/sparse_grid.hpp"

#include <algorithm>

namespace mpfd::mpm {

SparseGrid::SparseGrid(const grid::UniformGrid& grid) : grid_(grid) {
  std::size_t table_size = 1;
  for (int a = 0; a < 3; ++a) {
    const bool active = grid.is_active(a);
    offset_[a] = active ? 1 : 0;
    shift_[a] = active ? kBlockShift : 0;
    mask_[a] = active ? (1 << kBlockShift) - 1 : 0;
    block_dim_[a] = active ? 1 << kBlockShift : 1;
    // Nodes -1 .. cells + 1: the grid's nodes and one ghost layer each side.
    const int extent = active ? grid.cells()[a] + 3 : 1;
    blocks_[a] = (extent + block_dim_[a] - 1) / block_dim_[a];
    block_nodes_ *= static_cast<std::size_t>(block_dim_[a]);
    table_size *= static_cast<std::size_t>(blocks_[a]);
  }
  table_.assign(table_size, -1);
}

void SparseGrid::clear() {
  for (const std::int32_t id : active_) table_[static_cast<std::size_t>(id)] = -1;
  active_.clear();
}

std::int32_t SparseGrid::activate(const grid::Index3& lo, const grid::Index3& hi) {
  const int b0[3] = {lo[0] >> shift_[0], lo[1] >> shift_[1], lo[2] >> shift_[2]};
  const int b1[3] = {hi[0] >> shift_[0], hi[1] >> shift_[1], hi[2] >> shift_[2]};
  for (int bk = b0[2]; bk <= b1[2]; ++bk)
    for (int bj = b0[1]; bj <= b1[1]; ++bj)
      for (int bi = b0[0]; bi <= b1[0]; ++bi) {
        const std::size_t id = block_id(bi, bj, bk);
        if (table_[id] < 0) {
          table_[id] = static_cast<std::int32_t>(active_.size());
          active_.push_back(static_cast<std::int32_t>(id));
        }
      }
  return table_[block_id(b0[0], b0[1], b0[2])];
}

std::ptrdiff_t SparseGrid::find_node(const grid::Index3& storage) const {
  for (int a = 0; a < 3; ++a)
    if (storage[a] < 0 || (storage[a] >> shift_[a]) >= blocks_[a]) return -1;
  if (table_[block_id(storage[0] >> shift_[0], storage[1] >> shift_[1], storage[2] >> shift_[2])] <
      0)
    return -1;
  return static_cast<std::ptrdiff_t>(node(storage[0], storage[1], storage[2]));
}

void SparseGrid::allocate_nodes() {
  const std::size_t n = node_count();
  if (mass.size() < n) {  // warm-up only: the arrays keep their largest size
    mass.resize(n);
    for (int a = 0; a < 3; ++a) {
      momentum[a].resize(n);
      force[a].resize(n);
      remapped[a].resize(n);
    }
  }
  std::fill_n(mass.begin(), n, 0.0);
  for (int a = 0; a < 3; ++a) {
    std::fill_n(momentum[a].begin(), n, 0.0);
    std::fill_n(force[a].begin(), n, 0.0);
    std::fill_n(remapped[a].begin(), n, 0.0);
  }
}

grid::Index3 SparseGrid::node_coordinates(std::size_t n) const {
  const auto slot = n / block_nodes_;
  const auto local = static_cast<int>(n % block_nodes_);
  const auto id = static_cast<std::size_t>(active_[slot]);
  const int bi = static_cast<int>(id % static_cast<std::size_t>(blocks_[0]));
  const int bj = static_cast<int>((id / static_cast<std::size_t>(blocks_[0])) %
                                  static_cast<std::size_t>(blocks_[1]));
  const int bk = static_cast<int>(
      id / (static_cast<std::size_t>(blocks_[0]) * static_cast<std::size_t>(blocks_[1])));
  const int li = local % block_dim_[0];
  const int lj = (local / block_dim_[0]) % block_dim_[1];
  const int lk = local / (block_dim_[0] * block_dim_[1]);
  return {(bi << shift_[0]) + li, (bj << shift_[1]) + lj, (bk << shift_[2]) + lk};
}

void SparseGrid::bin_particles(std::span<const std::int32_t> home_slot) {
  const std::size_t slots = active_.size();
  if (bucket_begin_.size() < slots + 1) bucket_begin_.resize(slots + 1);
  if (order_.size() < home_slot.size()) order_.resize(home_slot.size());
  // Counting sort by home slot, stable: a bucket keeps the particles' order.
  std::fill_n(bucket_begin_.begin(), slots + 1, 0);
  for (const std::int32_t s : home_slot) ++bucket_begin_[static_cast<std::size_t>(s) + 1];
  for (std::size_t s = 0; s < slots; ++s) bucket_begin_[s + 1] += bucket_begin_[s];
  // Fill using the end of each bucket as a cursor, then shift back.
  for (std::size_t p = 0; p < home_slot.size(); ++p)
    order_[static_cast<std::size_t>(bucket_begin_[static_cast<std::size_t>(home_slot[p])]++)] =
        static_cast<std::int32_t>(p);
  for (std::size_t s = slots; s > 0; --s) bucket_begin_[s] = bucket_begin_[s - 1];
  bucket_begin_[0] = 0;

  // Colour of a home block: the parities of its block coordinates.
  if (colour_slots_.size() < slots) colour_slots_.resize(slots);
  std::array<std::int32_t, kColours + 1> count{};
  const auto colour_of = [&](std::size_t slot) {
    const auto id = static_cast<std::size_t>(active_[slot]);
    const auto bx = id % static_cast<std::size_t>(blocks_[0]);
    const auto by =
        (id / static_cast<std::size_t>(blocks_[0])) % static_cast<std::size_t>(blocks_[1]);
    const auto bz =
        id / (static_cast<std::size_t>(blocks_[0]) * static_cast<std::size_t>(blocks_[1]));
    return static_cast<int>((bx & 1U) | ((by & 1U) << 1U) | ((bz & 1U) << 2U));
  };
  for (std::size_t s = 0; s < slots; ++s)
    if (bucket_begin_[s + 1] > bucket_begin_[s])
      ++count[static_cast<std::size_t>(colour_of(s)) + 1];
  for (int c = 0; c < kColours; ++c) count[c + 1] += count[c];
  colour_begin_ = count;
  for (std::size_t s = 0; s < slots; ++s)
    if (bucket_begin_[s + 1] > bucket_begin_[s])
      colour_slots_[static_cast<std::size_t>(count[static_cast<std::size_t>(colour_of(s))]++)] =
          static_cast<std::int32_t>(s);
}

}  // namespace mpfd::mpm
