#include "fdm_solver/primitive_fields.hpp"

namespace mpfd::fdm {

void PrimitiveFields::compute(const EulerState& state, const std::vector<eos::AnyEos>& eos) {
  const std::size_t n = state.grid.cell_count();
  for (auto* f : {&velocity_x, &velocity_y, &velocity_z, &specific_internal_energy, &pressure,
                  &sound_speed, &material})
    f->resize(n);
  const auto& u = state.u;
#pragma omp parallel for schedule(static) if (n >= 32768)  // see euler_solver.cpp
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = u[kDensity][i];
    velocity_x[i] = u[kMomentumX][i] / rho;
    velocity_y[i] = u[kMomentumY][i] / rho;
    velocity_z[i] = u[kMomentumZ][i] / rho;
    const double kinetic = 0.5 * (velocity_x[i] * velocity_x[i] + velocity_y[i] * velocity_y[i] +
                                  velocity_z[i] * velocity_z[i]);
    const double e = u[kEnergy][i] / rho - kinetic;
    specific_internal_energy[i] = e;
    const auto& model = eos[state.material[i]];
    pressure[i] = eos::pressure(model, rho, e);
    sound_speed[i] = eos::sound_speed(model, rho, e);
    material[i] = state.material[i];
  }
}

}  // namespace mpfd::fdm
