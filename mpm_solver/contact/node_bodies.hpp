#pragma once
// What the contact kernels see of one background-grid node shared by several
// bodies (T §2.1.3): per body b, its nodal mass, momentum and mass gradient.
// The step gathers these from its per-body grid fields; the kernels know
// nothing of the grid's storage.

#include <Eigen/Core>
#include <cstddef>
#include <span>

namespace mpfd::mpm::contact {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

/// The bodies at one node, b = 0 .. count() - 1; all spans have the same length.
template <int Dim>
struct NodeBodies {
  /// m_I^{b,n}, T (2-12) summed over body b's particles; > 0 for a body at the node.
  std::span<const double> mass;
  /// p_I^b, T (2-9) over body b's particles: the momenta a kernel corrects.
  std::span<const Vec<Dim>> momentum;
  /// sum_p m_p grad N_I(x_p) over body b's particles, the numerator of T (2-23).
  /// It points out of body b: grad N_I at a particle points towards node I.
  std::span<const Vec<Dim>> mass_gradient;

  [[nodiscard]] std::size_t count() const { return mass.size(); }
};

}  // namespace mpfd::mpm::contact
