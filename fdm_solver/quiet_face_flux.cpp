#include "fdm_solver/quiet_face_flux.hpp"

#include "fdm_solver/cell_eos.hpp"

namespace mpfd::fdm {

QuietFaceFlux quiet_face_flux(const EulerState& state, const config::Boundaries& boundaries,
                              const std::vector<eos::AnyEos>& eos) {
  const auto& g = state.grid;
  const auto& n = g.cells();
  QuietFaceFlux q;
  for (int face = 0; face < 6; ++face) {
    const int a = face / 2, a1 = (a + 1) % 3, a2 = (a + 2) % 3;
    const bool mirror =
        boundaries[static_cast<config::Face>(face)] != config::BoundaryKind::outflow;
    const std::size_t lines = static_cast<std::size_t>(n[a1]) * n[a2];
    if (!g.is_active(a)) continue;  // no sweep, no flux through the faces of an unused axis
    for (auto& v : q.flux[face]) v.assign(lines, 0.0);
    for (int l2 = 0; l2 < n[a2]; ++l2)
      for (int l1 = 0; l1 < n[a1]; ++l1) {
        grid::Index3 cell{};
        cell[a] = face % 2 == 0 ? 0 : n[a] - 1;
        cell[a1] = l1;
        cell[a2] = l2;
        const std::size_t c = g.cell_index(cell);
        const std::size_t line = static_cast<std::size_t>(l1 + n[a1] * l2);
        const double rho = state.u[kDensity][c];
        const double m[3] = {state.u[kMomentumX][c], state.u[kMomentumY][c],
                             state.u[kMomentumZ][c]};
        const double e_total = state.u[kEnergy][c];
        const double e = specific_internal_energy(state, c);
        const double p = cell_pressure(state, eos, c, rho, e);
        const double un = mirror ? 0.0 : m[a] / rho;
        q.flux[face][kDensity][line] = rho * un;
        for (int b = 0; b < 3; ++b)
          q.flux[face][kMomentumX + static_cast<std::size_t>(b)][line] =
              m[b] * un + (b == a ? p : 0.0);
        q.flux[face][kEnergy][line] = (e_total + p) * un;
      }
    for (std::size_t v = 0; v < kVariables; ++v)
      for (const double f : q.flux[face][v]) q.total[face][v] += f;
  }
  return q;
}

}  // namespace mpfd::fdm
