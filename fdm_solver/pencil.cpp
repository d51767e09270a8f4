#include "fdm_solver/pencil.hpp"

namespace mpfd::fdm {

void Pencil::resize(std::size_t length) {
  const std::size_t entries = length * kMaxLanes;
  for (auto* group : {&u, &u_new, &ubar, &flux_bar, &flux, &diffusion})
    for (auto& v : *group) v.assign(entries, 0.0);
  for (auto* v : {&pressure, &sound_speed, &pressure_bar, &theta, &mix_gamma, &mix_pinf})
    v->assign(entries, 0.0);
  material.assign(entries, 0);
}

}  // namespace mpfd::fdm
