#pragma once
// Exact measure of the intersection of an axis-aligned box with a ball
// (3D: volume) or a disc (2D: area) centred at the origin, in closed form.
// The conservative 1D -> Cartesian remap (S, steps (1)-(4)) needs the volume
// of every cell-shell intersection; a shell is the difference of two balls.
//
// Reflections x_i -> -x_i (and a split where the box straddles x_i = 0)
// bring every piece into the first orthant; there inclusion-exclusion over
// the 2^d corners reduces a box to corners G(l) = |B_1 ∩ {x_i >= l_i}|,
// l_i >= 0, which are integrated exactly:
//   2D  C(a, b)    = (pi/2 - asin a - asin b)/2 - (a sqrt(1-a^2) + b sqrt(1-b^2))/2 + a b
//   3D  W(a, b, c) = F(X) - F(a),  X = sqrt(1 - b^2 - c^2),  F' = C scaled to the slice
// (derivation in coupler/remap/README.md). Round-off: a few ulp of the
// largest corner volume involved, i.e. ~1e-16 R h^2 for a cell of size h
// cut by a sphere of radius R.

#include <span>

namespace mpfd::coupler::remap {

/// |[lower, upper] ∩ {|x| <= radius}| for a box of dimension 2 or 3
/// (lower.size() == upper.size()); 0 for radius <= 0. Throws mpfd::Error
/// for another dimension or lower > upper.
[[nodiscard]] double ball_box_overlap(std::span<const double> lower, std::span<const double> upper,
                                      double radius);

}  // namespace mpfd::coupler::remap
