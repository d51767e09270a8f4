#pragma once
// The background grid of the spherical MPM: nodes i = 0 .. n-1 at r = i h.
// Node 0 sits at the centre and keeps zero velocity (symmetry). Node masses
// and forces are per unit solid angle, like the particles'.

#include <cstddef>
#include <vector>

namespace mpfd::mpm::spherical {

struct RadialGrid {
  double spacing = 0.0;          ///< h [m]
  std::vector<double> mass;      ///< m_I, T (2-12)
  std::vector<double> momentum;  ///< p_I, T (2-9), then p_I^{n+1}, T (2-13)
  std::vector<double> force;     ///< f_I = f_int + f_ext, T (2-14)
  std::vector<double> velocity;  ///< v_I^{n+1} from the remap, T (2-17)
  std::vector<double> dashpot;   ///< boundary dashpot eta_I, force -eta_I v_I^{n+1} [kg/(s sr)]

  void resize(std::size_t nodes) {
    for (auto* f : {&mass, &momentum, &force, &velocity, &dashpot}) f->assign(nodes, 0.0);
  }
  [[nodiscard]] std::size_t size() const noexcept { return mass.size(); }
  /// The radius of the last node [m]; particles must stay inside.
  [[nodiscard]] double outer_radius() const noexcept {
    return spacing * static_cast<double>(size() - 1);
  }
};

}  // namespace mpfd::mpm::spherical
