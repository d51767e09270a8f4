#include "fdm_solver/primitive_fields.hpp"

#include "common/core/parallel_for.hpp"
#include "fdm_solver/cell_eos.hpp"

namespace mpfd::fdm {

void PrimitiveFields::compute(const EulerState& state, const std::vector<eos::AnyEos>& eos) {
  const std::size_t n = state.grid.cell_count();
  for (auto* f : {&velocity_x, &velocity_y, &velocity_z, &specific_internal_energy, &pressure,
                  &sound_speed, &material})
    f->resize(n);
  const auto& u = state.u;
#pragma omp parallel for schedule(static) if (n >= static_cast <std::size_t>(kMinParallelCount))
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = u[kDensity][i];
    velocity_x[i] = u[kMomentumX][i] / rho;
    velocity_y[i] = u[kMomentumY][i] / rho;
    velocity_z[i] = u[kMomentumZ][i] / rho;
    const double kinetic = 0.5 * (velocity_x[i] * velocity_x[i] + velocity_y[i] * velocity_y[i] +
                                  velocity_z[i] * velocity_z[i]);
    const double e = u[kEnergy][i] / rho - kinetic;
    specific_internal_energy[i] = e;
    pressure[i] = cell_pressure(state, eos, i, rho, e);
    sound_speed[i] = cell_sound_speed(state, eos, i, rho, e);
    material[i] = state.material[i] == kMixedMaterial ? -1.0 : state.material[i];
  }
}

}  // namespace mpfd::fdm
