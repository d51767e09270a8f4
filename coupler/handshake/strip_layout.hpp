#pragma once
// The `strip_cells` region (proto/README.md §6): the two cell layers on either
// side of the MPM zone's boundary face, cell k-w outside the zone ("outer")
// and cell k-w+1 inside it ("inner", in the handshake zone), T Fig. 4.3/4.4.
// Its box is 2 cells thick along the face normal. A "face cell" t is one pair
// (outer, inner) across the face, numbered in C order of the box with the
// normal axis left out.

#include <cstddef>
#include <vector>

#include "coupler/handshake/index_box.hpp"

namespace mpfd::coupler::handshake {

template <int Dim>
struct StripLayout {
  ZoneFace face;
  IndexBox<Dim> box;                   ///< the strip_cells box
  std::vector<std::size_t> outer;      ///< per face cell: position of cell k-w in the strip
  std::vector<std::size_t> inner;      ///< per face cell: position of cell k-w+1 in the strip
  std::vector<Index<Dim>> inner_cell;  ///< per face cell: grid index of cell k-w+1

  [[nodiscard]] std::size_t face_cells() const { return outer.size(); }
  /// Grid index along the normal of the nodes on the face.
  [[nodiscard]] std::int64_t face_node_layer() const {
    return face.side > 0 ? box.lo[face.axis] + 1 : box.hi[face.axis] - 1;
  }
};

/// Pairs the cells of `strip` across `face`. Throws mpfd::Error unless the
/// box is 2 cells thick along face.axis.
template <int Dim>
[[nodiscard]] StripLayout<Dim> make_strip_layout(const IndexBox<Dim>& strip, const ZoneFace& face);

}  // namespace mpfd::coupler::handshake
