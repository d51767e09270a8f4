#pragma once
// How much a history oscillates (V5, T §3.4.4, Figs. 3.12–3.14: AFDMP's Mises
// histories are smooth where AUTODYN's edge history rings). An oscillation is
// counted as a local extremum whose topographic prominence exceeds a threshold:
// for a maximum v_i, the lower of the deepest drops before reaching a higher
// value on either side (or the series' end), v_i − max(min_left, min_right);
// minima as maxima of −v. A monotone history has none; one hump has one.

#include <cstddef>
#include <span>
#include <vector>

namespace mpfd::verification {

/// Interior local maxima and minima of `values` with prominence > `min_prominence`.
[[nodiscard]] int prominent_extrema(std::span<const double> values, double min_prominence);

/// Indices of the interior local maxima of `values` with prominence > `min_prominence`.
[[nodiscard]] std::vector<std::size_t> prominent_maxima(std::span<const double> values,
                                                        double min_prominence);

}  // namespace mpfd::verification
