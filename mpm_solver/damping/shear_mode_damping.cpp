#include "mpm_solver/damping/shear_mode_damping.hpp"

namespace mpfd::mpm::damping {

template <int Dim>
double shear_damping_coefficient(double particle_mass, double sound_speed, double cell_size,
                                 double q_s) {
  // T (2-48) is the 8-node cell's. A cell with one axis fewer sees half the
  // amplitude S per unit strain rate on half the nodes: 4 α_s gives it the
  // forces of the 8-node cell extruded along the missing axis (1D has no shear).
  double dimension_factor = 1;
  for (int axis = Dim; axis < 3; ++axis) dimension_factor *= 4;
  return dimension_factor * particle_mass / cell_size * q_s * sound_speed / 4;  // T (2-48)
}

template <int Dim>
Tensor<Dim> mode_amplitudes(const CellVectors<Dim>& velocity) {
  Tensor<Dim> s = Tensor<Dim>::Zero();
  for (int node = 0; node < kCellNodes<Dim>; ++node) {
    for (int k = 0; k < Dim; ++k) s.col(k) += natural_coordinate(node, k) * velocity[node];
  }
  return s;  // T (2-46)
}

template <int Dim>
CellVectors<Dim> shear_damping_forces(const CellVectors<Dim>& velocity, double alpha) {
  const Tensor<Dim> s = mode_amplitudes<Dim>(velocity);
  // Shear only (k != i), and its symmetric part: a rigid rotation has S_ik = -S_ki.
  Tensor<Dim> shear = 0.5 * (s + s.transpose());
  shear.diagonal().setZero();
  CellVectors<Dim> force;
  for (int node = 0; node < kCellNodes<Dim>; ++node) {
    Vec<Dim> coordinates;
    for (int k = 0; k < Dim; ++k) coordinates(k) = natural_coordinate(node, k);
    force[node] = -alpha * shear * coordinates;  // T (2-47), summed over the modes k
  }
  return force;
}

#define MPFD_INSTANTIATE_DAMPING(Dim)                                             \
  template double shear_damping_coefficient<Dim>(double, double, double, double); \
  template Tensor<Dim> mode_amplitudes<Dim>(const CellVectors<Dim>&);             \
  template CellVectors<Dim> shear_damping_forces<Dim>(const CellVectors<Dim>&, double);
MPFD_INSTANTIATE_DAMPING(1)
MPFD_INSTANTIATE_DAMPING(2)
MPFD_INSTANTIATE_DAMPING(3)
#undef MPFD_INSTANTIATE_DAMPING

}  // namespace mpfd::mpm::damping
