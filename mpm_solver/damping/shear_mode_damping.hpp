#pragma once
// Shear-mode damping of one background cell, T (2-33) ... (2-48), for long air
// runs: air has no shear stiffness, so round-off shear in a cell grows until
// the run fails (T Fig. 2.4). The cell's node velocities v_i (one entry per
// node) project on the mode vectors Λ_k, whose entries Λ_kI are the natural
// coordinates of node I, T (2-39) ... (2-41), Table 2.1:
//   S_ik = Λ_k^T v_i                                  T (2-46)
//   f_i^I = -α_s Σ_{k≠i} ½ (S_ik + S_ki) Λ_kI         T (2-47), symmetrised
//   α_s = (Σ_p m_p / Δx) Q_s c / 4                    T (2-48), 3D
// Read as built (README "Misprints"): only k ≠ i is shear (the text; (2-46)
// prints i, k = 1..3, which would also damp compression); S is symmetrised so
// that a rigid rotation is not braked and angular momentum is kept; 2D uses
// 4 α_s, so that a 2D cell damps as the 3D cell extruded (1D has no shear mode).
// The hourglass modes Γ (2-42) ... (2-45) are orthogonal to Λ and left alone.

#include <Eigen/Core>
#include <array>

namespace mpfd::mpm::damping {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;
template <int Dim>
using Tensor = Eigen::Matrix<double, Dim, Dim>;

template <int Dim>
inline constexpr int kCellNodes = 1 << Dim;

/// One vector per node of a cell. Nodes are numbered x fastest, as the grid
/// numbers them: node = b_x + 2 b_y + 4 b_z with b = 1 on the upper face
/// (not Table 2.1's order; the formulas depend only on each node's coordinates).
template <int Dim>
using CellVectors = std::array<Vec<Dim>, kCellNodes<Dim>>;

/// Λ_kI: natural coordinate (ξ_I, η_I, ζ_I of Table 2.1) of `node` along `axis`.
constexpr double natural_coordinate(int node, int axis) {
  return ((node >> axis) & 1) != 0 ? 1.0 : -1.0;
}

/// α_s, T (2-48) (times 4 in 2D): `particle_mass` is Σ m_p over the particles
/// in the cell, `sound_speed` c of their material, `cell_size` Δx (cells are
/// cubes on the active axes), `q_s` the user's Q_s >= 0.
template <int Dim>
[[nodiscard]] double shear_damping_coefficient(double particle_mass, double sound_speed,
                                               double cell_size, double q_s);

/// S_ik = Λ_k^T v_i, T (2-46): row i is the velocity component, column k the mode.
template <int Dim>
[[nodiscard]] Tensor<Dim> mode_amplitudes(const CellVectors<Dim>& velocity);

/// The damping force on each node of the cell, T (2-47) symmetrised, from the
/// nodes' velocities v_I = p_I / m_I. The forces sum to zero, have no moment
/// about any point, and do negative work for any velocities.
template <int Dim>
[[nodiscard]] CellVectors<Dim> shear_damping_forces(const CellVectors<Dim>& velocity, double alpha);

/// The cell's damping stiffness 2^Dim α_s: the force is at most this times the
/// node velocity (the pure shear mode reaches it). An explicit step loses
/// kinetic energy to the damping if dt Σ_cells 2^Dim α_s <= 2 m_I at every node.
template <int Dim>
[[nodiscard]] constexpr double shear_damping_stiffness(double alpha) {
  return kCellNodes<Dim> * alpha;
}

}  // namespace mpfd::mpm::damping
