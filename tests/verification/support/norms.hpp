#pragma once
// L1 error of a cell-centred 1D solution on the uniform grid of N cells over
// [x_min, x_max] (dx = (x_max - x_min) / N, x_i = x_min + (i + 1/2) dx),
// normalised by the domain length so that it is the mean absolute error:
//   L1 = sum_i |u_i - v_i| dx / (x_max - x_min)
// with v_i either
//   * the exact solution at the cell centre, v_i = f(x_i): the usual choice for
//     Sod-type comparisons, first order in dx at
//     shocks whatever v_i is; or
//   * the exact cell average (1/dx) int f dx by n-point Gauss-Legendre per cell:
//     the quantity a finite-volume scheme actually approximates, exact for
//     polynomials of degree 2n - 1; it differs from the centre value by
//     dx^2 f'' / 24 + O(dx^4) in smooth regions.

#include <functional>
#include <span>

namespace mpfd::verification {

/// L1 against point values at the cell centres.
[[nodiscard]] double l1_error_at_centres(std::span<const double> cells, double x_min, double x_max,
                                         const std::function<double(double)>& exact);

/// L1 against cell averages of `exact` by `gauss_points`-point Gauss-Legendre.
[[nodiscard]] double l1_error_of_cell_averages(std::span<const double> cells, double x_min,
                                               double x_max,
                                               const std::function<double(double)>& exact,
                                               int gauss_points = 3);

}  // namespace mpfd::verification
