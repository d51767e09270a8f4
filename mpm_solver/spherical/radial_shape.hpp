#pragma once
// Shape functions of a uniform radial grid with node i at r = i h (S eq. (4),
// one-dimensional form). Linear: a point in cell c = floor(r/h) has
// N_c = 1 - xi, N_{c+1} = xi (xi = r/h - c), dN_c/dr = -1/h, dN_{c+1}/dr = 1/h.
// GIMP (Bardenhagen & Kober 2004) in spherical form: a particle spans the
// shell D = [r - l, r + l] with l = h / (2 particles_per_cell) and its weights
// are the exact moments of the hat over D, normalised by V_D = int_D r^2 dr:
//   S_I = int_D N_I r^2 dr / V_D,  B_I = int_D N_I' r^2 dr / V_D,
//   C_I = int_D N_I r dr / V_D   (the hoop weight; C_I = N_I / r for a point).
// The moments remove the force jump of a particle crossing a node, and since
// B_I + 2 C_I = [N_I r^2]_D / V_D, shells that tile [0, R] give no nodal force
// under uniform stress, at r = 0 or elsewhere.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace mpfd::mpm::spherical {

struct RadialWeights {
  std::size_t first = 0;             ///< index of the first node
  std::array<double, 3> value{};     ///< N (or S) of nodes first, first+1, first+2
  std::array<double, 3> gradient{};  ///< dN/dr (GIMP: B_I) [1/m]
  std::array<double, 3> hoop{};      ///< N / r (GIMP: C_I) [1/m]
};

[[nodiscard]] inline RadialWeights linear_weights(double r, double inverse_spacing) noexcept {
  const double s = r * inverse_spacing;
  const double c = std::floor(s);
  const double xi = s - c;
  return {static_cast<std::size_t>(c),
          {1.0 - xi, xi, 0.0},
          {-inverse_spacing, inverse_spacing, 0.0},
          {(1.0 - xi) / r, xi / r, 0.0}};
}

/// The GIMP weights of the shell [r - l, r + l] (0 < l <= h/2, r >= l).
[[nodiscard]] inline RadialWeights gimp_weights(double r, double spacing,
                                                double half_width) noexcept {
  const double a = std::max(0.0, r - half_width);  // no shell inside the centre
  const double b = r + half_width;
  const double volume = (b * b * b - a * a * a) / 3.0;
  const auto first = static_cast<std::size_t>(std::floor(a / spacing));
  RadialWeights w;
  w.first = first;
  // Each cell [x0, x0 + h] that D overlaps: N_left = (x0 + h - r)/h, N_right = (r - x0)/h.
  for (std::size_t cell = first; cell < first + 2; ++cell) {
    const double x0 = static_cast<double>(cell) * spacing;
    const double lo = std::max(a, x0);
    const double hi = std::min(b, x0 + spacing);
    if (hi <= lo) continue;
    const double m1 = (hi * hi - lo * lo) / 2.0;                      // int r dr
    const double m2 = (hi * hi * hi - lo * lo * lo) / 3.0;            // int r^2 dr
    const double m3 = (hi * hi * hi * hi - lo * lo * lo * lo) / 4.0;  // int r^3 dr
    const std::size_t k = cell - first;
    const double right_value = (m3 - x0 * m2) / spacing;  // int N_right r^2 dr
    const double right_hoop = (m2 - x0 * m1) / spacing;   // int N_right r dr
    w.value[k] += (m2 - right_value) / volume;
    w.value[k + 1] += right_value / volume;
    w.gradient[k] -= m2 / spacing / volume;
    w.gradient[k + 1] += m2 / spacing / volume;
    w.hoop[k] += (m1 - right_hoop) / volume;
    w.hoop[k + 1] += right_hoop / volume;
  }
  return w;
}

}  // namespace mpfd::mpm::spherical
