#include "fdm_solver/sweep_kernel.hpp"

#include <algorithm>
#include <cmath>

namespace mpfd::fdm {
namespace {

/// Specific internal energy from the rotated conserved state.
inline double specific_energy(double rho, double mn, double mt1, double mt2, double e_total) {
  return (e_total - 0.5 * (mn * mn + mt1 * mt1 + mt2 * mt2) / rho) / rho;
}

/// True if every cell in [first, last) has the same material.
bool uniform_material(const std::uint8_t* material, std::size_t first, std::size_t last) {
  for (std::size_t i = first + 1; i < last; ++i)
    if (material[i] != material[first]) return false;
  return true;
}

/// Euler flux along the sweep axis of state u at pressure p, T (2-50).
inline void euler_flux(const std::array<std::vector<double>, 5>& u, const double* pressure,
                       std::array<std::vector<double>, 5>& flux, std::size_t first,
                       std::size_t last) {
  const double* rho = u[kRho].data();
  const double* mn = u[kMn].data();
  const double* mt1 = u[kMt1].data();
  const double* mt2 = u[kMt2].data();
  const double* e = u[kE].data();
  double* f0 = flux[kRho].data();
  double* f1 = flux[kMn].data();
  double* f2 = flux[kMt1].data();
  double* f3 = flux[kMt2].data();
  double* f4 = flux[kE].data();
#pragma omp simd
  for (std::size_t i = first; i < last; ++i) {
    const double un = mn[i] / rho[i];
    f0[i] = mn[i];
    f1[i] = mn[i] * un + pressure[i];
    f2[i] = mt1[i] * un;
    f3[i] = mt2[i] * un;
    f4[i] = (e[i] + pressure[i]) * un;
  }
}

}  // namespace

void compute_pressure(std::span<const eos::AnyEos> eos, const std::uint8_t* material,
                      const std::array<std::vector<double>, 5>& u, double* pressure,
                      double* sound_speed, std::size_t first, std::size_t last) {
  const double* rho = u[kRho].data();
  const double* mn = u[kMn].data();
  const double* mt1 = u[kMt1].data();
  const double* mt2 = u[kMt2].data();
  const double* e_total = u[kE].data();
  const auto kernel = [&](const auto& model, std::size_t begin, std::size_t end) {
    if (sound_speed == nullptr) {
#pragma omp simd
      for (std::size_t i = begin; i < end; ++i)
        pressure[i] =
            model.pressure(rho[i], specific_energy(rho[i], mn[i], mt1[i], mt2[i], e_total[i]));
      return;
    }
#pragma omp simd
    for (std::size_t i = begin; i < end; ++i) {
      const double e = specific_energy(rho[i], mn[i], mt1[i], mt2[i], e_total[i]);
      pressure[i] = model.pressure(rho[i], e);
      sound_speed[i] = model.sound_speed(rho[i], e);
    }
  };
  if (first >= last) return;
  // One dispatch per pencil in the common case of one material along it.
  if (uniform_material(material, first, last)) {
    std::visit([&](const auto& model) { kernel(model, first, last); }, eos[material[first]]);
    return;
  }
  for (std::size_t i = first; i < last; ++i)
    std::visit([&](const auto& model) { kernel(model, i, i + 1); }, eos[material[i]]);
}

std::optional<BadCell> sweep_pencil(Pencil& pencil, std::size_t lanes, std::size_t first,
                                    std::size_t last, const SweepStep& step,
                                    std::span<const eos::AnyEos> eos, EndFluxes& ends) {
  // Flattened entries j = position * lanes + lane; the neighbour along the
  // line is j +- w.
  const std::size_t w = lanes;
  const std::size_t begin = first * w, end = last * w;
  auto& u = pencil.u;
  auto& ubar = pencil.ubar;
  auto& flux = pencil.flux;
  auto& half = pencil.half;
  auto& diff = pencil.diffusion;
  double* p = pencil.pressure.data();
  double* c = pencil.sound_speed.data();
  double* theta = pencil.theta.data();
  const std::uint8_t* mat = pencil.material.data();
  const double courant = step.dt / step.dx;

  // 1. Pressure and sound speed on the whole stencil; refuse unphysical cells.
  compute_pressure(eos, mat, u, p, c, begin - 3 * w, end + 3 * w);
  for (std::size_t j = begin; j < end; ++j)
    if (!(u[kRho][j] > 0.0) || !(p[j] > 0.0) || !std::isfinite(u[kE][j]))
      return BadCell{j / w, j % w, u[kRho][j], p[j]};

  // 2. Shock switch, T (2-57): 1 at a jump, 0 where the density is linear.
  const double* rho = u[kRho].data();
#pragma omp simd
  for (std::size_t j = begin - 2 * w; j < end + 2 * w; ++j) {
    const double right = std::abs(rho[j + w] - rho[j]);
    const double left = std::abs(rho[j] - rho[j - w]);
    const double sum = right + left;
    theta[j] = sum > 0.0 ? std::abs(right - left) / sum : 0.0;
  }
  // Viscous exchange across the face between j and j + w, T (2-56), (2-58).
  for (std::size_t v = 0; v < 5; ++v) {
    const double* uv = u[v].data();
    double* d = diff[v].data();
#pragma omp simd
    for (std::size_t j = begin - 2 * w; j < end + w; ++j) {
      const double nu = std::min(1.0, courant * std::max(c[j], c[j + w]));
      const double eta = nu * (1.0 - nu);
      d[j] = 0.5 * step.viscosity * eta * std::max(theta[j], theta[j + w]) * (uv[j + w] - uv[j]);
    }
  }
  for (std::size_t v = 0; v < 5; ++v) {
    const double* uv = u[v].data();
    const double* d = diff[v].data();
    double* ub = ubar[v].data();
#pragma omp simd
    for (std::size_t j = begin - w; j < end + w; ++j) ub[j] = uv[j] + d[j] - d[j - w];
  }

  // 3. Richtmyer predictor at the faces between j and j + w.
  compute_pressure(eos, mat, ubar, p, nullptr, begin - w, end + w);
  euler_flux(ubar, p, flux, begin - w, end + w);
  for (std::size_t v = 0; v < 5; ++v) {
    const double* ub = ubar[v].data();
    const double* f = flux[v].data();
    double* h = half[v].data();
#pragma omp simd
    for (std::size_t j = begin - w; j < end; ++j)
      h[j] = 0.5 * (ub[j] + ub[j + w]) - 0.5 * courant * (f[j + w] - f[j]);
  }
  // Face pressure: the EOS of the material on both sides, or the mean of the
  // two EOS where the face separates two materials.
  compute_pressure(eos, mat, half, p, nullptr, begin - w, end);
  for (std::size_t j = begin - w; j < end; ++j) {
    if (mat[j] == mat[j + w]) continue;
    const double e =
        specific_energy(half[kRho][j], half[kMn][j], half[kMt1][j], half[kMt2][j], half[kE][j]);
    p[j] = 0.5 * (eos::pressure(eos[mat[j]], half[kRho][j], e) +
                  eos::pressure(eos[mat[j + w]], half[kRho][j], e));
  }
  euler_flux(half, p, flux, begin - w, end);

  // 4. Corrector, and what crossed the range's two ends.
  for (std::size_t v = 0; v < 5; ++v) {
    const double* ub = ubar[v].data();
    const double* f = flux[v].data();
    const double* d = diff[v].data();
    double* uv = u[v].data();
#pragma omp simd
    for (std::size_t j = begin; j < end; ++j) uv[j] = ub[j] - courant * (f[j] - f[j - w]);
    for (std::size_t lane = 0; lane < w; ++lane) {
      ends.lower[v] += step.dt * f[begin - w + lane] - step.dx * d[begin - w + lane];
      ends.upper[v] += step.dt * f[end - w + lane] - step.dx * d[end - w + lane];
    }
  }
  return std::nullopt;
}

void Pencil::resize(std::size_t length) {
  const std::size_t entries = length * kMaxLanes;
  for (auto* group : {&u, &ubar, &flux, &half, &diffusion})
    for (auto& v : *group) v.assign(entries, 0.0);
  pressure.assign(entries, 0.0);
  sound_speed.assign(entries, 0.0);
  theta.assign(entries, 0.0);
  material.assign(entries, 0);
}

}  // namespace mpfd::fdm
