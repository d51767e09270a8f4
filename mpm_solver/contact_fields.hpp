#pragma once
// Per-body nodal fields of the multi-velocity-field contact (T §2.1.3), kept
// only at the nodes where two or more bodies meet (the local multi-grid of Ma
// et al. the thesis uses): every other node keeps the single velocity field.
// A node is shared when the stencils of particles of two bodies reach it; the
// per-body mass, momentum, mass gradient and force of its K bodies sit at
// [k * K + b], k the node's index among the shared nodes.

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mpfd::mpm {

struct ContactFields {
  static constexpr int kMaxBodies = 16;

  int bodies = 0;                               ///< K: every body and charge has a field
  std::vector<std::int32_t> shared;             ///< per node: k, or -1 where one body (or none) is
  std::vector<std::size_t> node_of;             ///< k -> node
  std::vector<double> mass;                     ///< m_I^b (2-12) [kg]
  std::array<std::vector<double>, 3> momentum;  ///< p_I^b (2-9), then p_I^{b,n+1} / m_I^b
  std::array<std::vector<double>, 3> gradient;  ///< sum m_p grad N_I, numerator of (2-23)
  std::array<std::vector<double>, 3> force;     ///< f_I^b, + f^{b,c} (2-27), then / m_I^b
  std::array<std::vector<double>, 3> remapped;  ///< sum m_p N v_p^{n+1} (2-17), then / m_I^b

  /// Starts a step's marking over `nodes` nodes: no node shared.
  void begin_marking(std::size_t nodes) { shared.assign(nodes, -1); }
  /// Body `body`'s stencil reaches `node`. Marks hold -1 (none), b (one body), K (several).
  void mark(std::size_t node, int body) {
    std::int32_t& m = shared[node];
    if (m == -1)
      m = body;
    else if (m != body)
      m = bodies;
  }
  /// Numbers the shared nodes k = 0, 1, ... (the others -1) and zeroes their fields.
  void compact();
  [[nodiscard]] std::size_t count() const { return node_of.size(); }
  [[nodiscard]] std::size_t at(std::int32_t k, int body) const {
    return static_cast<std::size_t>(k) * static_cast<std::size_t>(bodies) +
           static_cast<std::size_t>(body);
  }
};

}  // namespace mpfd::mpm
