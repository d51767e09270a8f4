#pragma once
// Linear shape functions of a uniform radial grid with node i at r = i h:
// a point in cell c = floor(r/h) has N_c = 1 - xi, N_{c+1} = xi, xi = r/h - c,
// and dN_c/dr = -1/h, dN_{c+1}/dr = 1/h (S eq. (4), one-dimensional form).

#include <cmath>
#include <cstddef>

namespace mpfd::mpm::spherical {

struct RadialWeights {
  std::size_t cell = 0;  ///< left node index c
  double left = 0.0;     ///< N_c
  double right = 0.0;    ///< N_{c+1}
};

[[nodiscard]] inline RadialWeights radial_weights(double r, double inverse_spacing) noexcept {
  const double s = r * inverse_spacing;
  const double c = std::floor(s);
  const double xi = s - c;
  return {static_cast<std::size_t>(c), 1.0 - xi, xi};
}

}  // namespace mpfd::mpm::spherical
