#include "fdm_solver/sweep_kernel.hpp"

#include <algorithm>
#include <cmath>

#include "fdm_solver/mixture_eos.hpp"

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

void compute_pressure(const EosView& eos, const std::array<std::vector<double>, 5>& u,
                      double* pressure, double* sound_speed, std::size_t first, std::size_t last) {
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
  const std::uint8_t* material = eos.material;
  // One dispatch per pencil in the common case of one material along it.
  if (material[first] != kMixedMaterial && uniform_material(material, first, last)) {
    std::visit([&](const auto& model) { kernel(model, first, last); }, eos.models[material[first]]);
    return;
  }
  for (std::size_t i = first; i < last; ++i) {
    if (material[i] == kMixedMaterial)
      kernel(StiffenedGas{eos.mix_gamma[i], eos.mix_pinf[i]}, i, i + 1);
    else
      std::visit([&](const auto& model) { kernel(model, i, i + 1); }, eos.models[material[i]]);
  }
}

/// Pressure of entry j's EOS at the state (rho, e).
double pressure_of(const EosView& eos, std::size_t j, double rho, double e) {
  if (eos.material[j] == kMixedMaterial)
    return StiffenedGas{eos.mix_gamma[j], eos.mix_pinf[j]}.pressure(rho, e);
  return eos::pressure(eos.models[eos.material[j]], rho, e);
}

/// Sound speed of entry j's EOS at the state (rho, e).
double sound_speed_of(const EosView& eos, std::size_t j, double rho, double e) {
  if (eos.material[j] == kMixedMaterial)
    return StiffenedGas{eos.mix_gamma[j], eos.mix_pinf[j]}.sound_speed(rho, e);
  return eos::sound_speed(eos.models[eos.material[j]], rho, e);
}

/// True if entry j holds a state the next sweep can use: density and
/// internal energy positive, and for a mixed cell's fitted EOS the pressure.
bool physical(const Pencil& p, const EosView& eos, std::size_t j) {
  const auto& u = p.u;
  const double rho = u[kRho][j];
  const double internal =
      u[kE][j] -
      0.5 * (u[kMn][j] * u[kMn][j] + u[kMt1][j] * u[kMt1][j] + u[kMt2][j] * u[kMt2][j]) / rho;
  if (!(rho > 0.0) || !(internal > 0.0)) return false;
  return eos.material[j] != kMixedMaterial || pressure_of(eos, j, rho, internal / rho) > 0.0;
}

/// True if every entry of [begin, end) passes physical(): a vectorised scan
/// for the common case, so the per-entry test runs only where one fails.
bool all_physical(const Pencil& p, const EosView& eos, std::size_t begin, std::size_t end) {
  const double* rho = p.u[kRho].data();
  const double* mn = p.u[kMn].data();
  const double* mt1 = p.u[kMt1].data();
  const double* mt2 = p.u[kMt2].data();
  const double* e_total = p.u[kE].data();
  int bad = 0;
#pragma omp simd reduction(+ : bad)
  for (std::size_t j = begin; j < end; ++j) {
    const double internal =
        e_total[j] - 0.5 * (mn[j] * mn[j] + mt1[j] * mt1[j] + mt2[j] * mt2[j]) / rho[j];
    bad += !(rho[j] > 0.0) | !(internal > 0.0) | (eos.material[j] == kMixedMaterial);
  }
  if (bad == 0) return true;
  for (std::size_t j = begin; j < end; ++j)
    if (!physical(p, eos, j)) return false;
  return true;
}

/// Rusanov (local Lax-Friedrichs) flux of the face between entries j and
/// j + w from the viscous states ubar, written into the flux arrays:
/// F = (F(U_L) + F(U_R))/2 - s (U_R - U_L)/2, s = max(|u| + c) of the two.
void rusanov_face(Pencil& p, const EosView& eos, std::size_t j, std::size_t w) {
  std::array<double, 5> f_side[2];
  double speed = 0.0;
  for (int side = 0; side < 2; ++side) {
    const std::size_t k = j + static_cast<std::size_t>(side) * w;
    const double rho = p.ubar[kRho][k], mn = p.ubar[kMn][k];
    const double e = specific_energy(rho, mn, p.ubar[kMt1][k], p.ubar[kMt2][k], p.ubar[kE][k]);
    const double pressure = pressure_of(eos, k, rho, e);
    const double un = mn / rho;
    speed = std::max(speed, std::abs(un) + sound_speed_of(eos, k, rho, e));
    f_side[side] = {mn, mn * un + pressure, p.ubar[kMt1][k] * un, p.ubar[kMt2][k] * un,
                    (p.ubar[kE][k] + pressure) * un};
  }
  for (std::size_t v = 0; v < 5; ++v)
    p.flux[v][j] =
        0.5 * (f_side[0][v] + f_side[1][v]) - 0.5 * speed * (p.ubar[v][j + w] - p.ubar[v][j]);
}

/// The a-posteriori positivity fallback (in the spirit of MOOD, Clain, Diot &
/// Loubere 2011): every cell of [begin, end) whose Lax-Wendroff update is not
/// physical gets the first-order, positivity-preserving Rusanov flux at both
/// its faces, and it and its neighbours are updated again from ubar. Faces
/// are shared, so the update stays conservative. Returns true if it changed
/// anything (the caller repeats, for cells whose new face flux hurt them).
bool repair_unphysical_cells(Pencil& p, const EosView& eos, std::size_t w, std::size_t begin,
                             std::size_t end, double courant) {
  if (all_physical(p, eos, begin, end)) return false;
  bool changed = false;
  for (std::size_t j = begin; j < end; ++j) {
    if (physical(p, eos, j)) continue;
    const bool lower_done = p.theta[j - w] < 0.0, upper_done = p.theta[j] < 0.0;
    if (lower_done && upper_done) continue;  // already first order: let the next check report it
    // theta of the face's left cell is no longer needed: it marks Rusanov faces.
    if (!lower_done) rusanov_face(p, eos, j - w, w), p.theta[j - w] = -1.0;
    if (!upper_done) rusanov_face(p, eos, j, w), p.theta[j] = -1.0;
    for (const std::size_t k : {j - w, j, j + w}) {
      if (k < begin || k >= end) continue;
      for (std::size_t v = 0; v < 5; ++v)
        p.u[v][k] = p.ubar[v][k] - courant * (p.flux[v][k] - p.flux[v][k - w]);
    }
    changed = true;
  }
  return changed;
}

/// Passes of the fallback: a repaired face can in turn hurt a neighbour.
constexpr int kFallbackPasses = 3;

std::optional<BadCell> sweep_pencil(Pencil& pencil, std::size_t lanes, std::size_t first,
                                    std::size_t last, const SweepStep& step,
                                    std::span<const eos::AnyEos> models, EndFluxes& ends) {
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
  const EosView eos{models, mat, pencil.mix_gamma.data(), pencil.mix_pinf.data()};
  const double courant = step.dt / step.dx;

  // 1. Pressure and sound speed on the whole stencil; refuse unphysical cells.
  compute_pressure(eos, u, p, c, begin - 3 * w, end + 3 * w);
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
  // The sound speed is no longer needed: its array keeps the pressure of ubar.
  double* p_ubar = c;
  compute_pressure(eos, ubar, p_ubar, nullptr, begin - w, end + w);
  euler_flux(ubar, p_ubar, flux, begin - w, end + w);
  for (std::size_t v = 0; v < 5; ++v) {
    const double* ub = ubar[v].data();
    const double* f = flux[v].data();
    double* h = half[v].data();
#pragma omp simd
    for (std::size_t j = begin - w; j < end; ++j)
      h[j] = 0.5 * (ub[j] + ub[j + w]) - 0.5 * courant * (f[j + w] - f[j]);
  }
  // Face pressure: the EOS of the material on both sides. Where the face
  // separates two materials (or a mixed cell's own fit), the half-step state
  // blends the two and no single EOS applies; pressure is continuous across a
  // contact, so the face takes the mean of the two cells' pressures.
  compute_pressure(eos, half, p, nullptr, begin - w, end);
  for (std::size_t j = begin - w; j < end; ++j)
    if (mat[j] != mat[j + w] || mat[j] == kMixedMaterial) p[j] = 0.5 * (p_ubar[j] + p_ubar[j + w]);
  euler_flux(half, p, flux, begin - w, end);

  // 4. Corrector, then the positivity fallback, then what crossed the ends.
  for (std::size_t v = 0; v < 5; ++v) {
    const double* ub = ubar[v].data();
    const double* f = flux[v].data();
    double* uv = u[v].data();
#pragma omp simd
    for (std::size_t j = begin; j < end; ++j) uv[j] = ub[j] - courant * (f[j] - f[j - w]);
  }
  for (int pass = 0;
       pass < kFallbackPasses && repair_unphysical_cells(pencil, eos, w, begin, end, courant);
       ++pass) {
  }
  for (std::size_t v = 0; v < 5; ++v) {
    const double* f = flux[v].data();
    const double* d = diff[v].data();
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
  mix_gamma.assign(entries, 0.0);
  mix_pinf.assign(entries, 0.0);
}

}  // namespace mpfd::fdm
