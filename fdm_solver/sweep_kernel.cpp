#include "fdm_solver/sweep_kernel.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <type_traits>

#include "fdm_solver/cell_kinematics.hpp"
#include "fdm_solver/mixture_eos.hpp"

// This file is compiled once per instruction set (fdm_solver/CMakeLists.txt);
// sweep_dispatch.cpp picks one at run time.
#ifndef MPFD_SWEEP_ISA
#define MPFD_SWEEP_ISA isa_baseline
#endif

namespace mpfd::fdm {
namespace {

/// Entries per chunk of the staged sweep (rounded to whole positions): a
/// whole x-line of up to 256 cells, or 16 positions of a 16-lane block, and
/// its stencil lag stay within L2. Measured on the 128^3 blast (CPU time,
/// 1 thread): 32 entries +10 %, 64 +5 %, 128 and 512 within 2 %, 4096 +4 %.
constexpr std::size_t kChunkEntries = 256;

/// Passes of the fallback: a repaired face can in turn hurt a neighbour.
constexpr int kFallbackPasses = 3;

/// Internal energy per volume, E - |m|^2 / (2 rho) [J/m^3]: the positivity test.
inline double internal_energy_density(double rho, double m1, double m2, double m3, double e_total) {
  return e_total - 0.5 * (m1 * m1 + m2 * m2 + m3 * m3) / rho;
}

/// Every entry of the block holds one material: its model, inlined.
template <class Model>
struct OneModel {
  static constexpr bool kSeveral = false;
  const Model& model;
  [[nodiscard]] double pressure(std::size_t, double rho, double e) const noexcept {
    return model.pressure(rho, e);
  }
  [[nodiscard]] double sound_speed(std::size_t, double rho, double e) const noexcept {
    return model.sound_speed(rho, e);
  }
};

/// Entries of several materials, or mixed cells: each entry's own EOS.
struct EntryModels {
  static constexpr bool kSeveral = true;
  std::span<const eos::AnyEos> models;
  const std::uint8_t* material;
  const double* mix_gamma;
  const double* mix_pinf;
  [[nodiscard]] double pressure(std::size_t j, double rho, double e) const {
    if (material[j] == kMixedMaterial)
      return StiffenedGas{mix_gamma[j], mix_pinf[j]}.pressure(rho, e);
    return eos::pressure(models[material[j]], rho, e);
  }
  [[nodiscard]] double sound_speed(std::size_t j, double rho, double e) const {
    if (material[j] == kMixedMaterial)
      return StiffenedGas{mix_gamma[j], mix_pinf[j]}.sound_speed(rho, e);
    return eos::sound_speed(models[material[j]], rho, e);
  }
};

/// True if entry j holds a state the next sweep can use: density and
/// internal energy positive, and for a mixed cell's fitted EOS the pressure.
bool physical(const Pencil& p, const EntryModels& eos, std::size_t j) {
  const auto& u = p.u_new;
  const double rho = u[kRho][j];
  const double internal = internal_energy_density(rho, u[kMn][j], u[kMt1][j], u[kMt2][j], u[kE][j]);
  if (!(rho > 0.0) || !(internal > 0.0)) return false;
  return eos.material[j] != kMixedMaterial || eos.pressure(j, rho, internal / rho) > 0.0;
}

/// True if every entry of [begin, end) passes physical(): a vectorised scan
/// for the common case, so the per-entry test runs only where one fails.
bool all_physical(const Pencil& p, const EntryModels& eos, std::size_t begin, std::size_t end) {
  const double* rho = p.u_new[kRho].data();
  const double* mn = p.u_new[kMn].data();
  const double* mt1 = p.u_new[kMt1].data();
  const double* mt2 = p.u_new[kMt2].data();
  const double* e_total = p.u_new[kE].data();
  int bad = 0;
#pragma omp simd reduction(+ : bad)
  for (std::size_t j = begin; j < end; ++j) {
    const double internal = internal_energy_density(rho[j], mn[j], mt1[j], mt2[j], e_total[j]);
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
void rusanov_face(Pencil& p, const EntryModels& eos, std::size_t j, std::size_t w) {
  std::array<double, 5> f_side[2];
  double speed = 0.0;
  for (int side = 0; side < 2; ++side) {
    const std::size_t k = j + static_cast<std::size_t>(side) * w;
    const double rho = p.ubar[kRho][k], mn = p.ubar[kMn][k];
    const double inv_rho = 1.0 / rho;
    const double e =
        internal_energy_per_mass(inv_rho, mn, p.ubar[kMt1][k], p.ubar[kMt2][k], p.ubar[kE][k]);
    const double pressure = eos.pressure(k, rho, e);
    const double un = mn * inv_rho;
    speed = std::max(speed, std::abs(un) + eos.sound_speed(k, rho, e));
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
bool repair_unphysical_cells(Pencil& p, const EntryModels& eos, std::size_t w, std::size_t begin,
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
        p.u_new[v][k] = p.ubar[v][k] - courant * (p.flux[v][k] - p.flux[v][k - w]);
    }
    changed = true;
  }
  return changed;
}

/// The pencil's arrays as raw pointers, for the staged loops.
struct Views {
  std::array<double*, 5> u, u_new, ubar, flux_bar, flux, diffusion;
  double* pressure;
  double* sound_speed;
  double* pressure_bar;
  double* theta;
  const std::uint8_t* material;

  explicit Views(Pencil& p)
      : pressure(p.pressure.data()),
        sound_speed(p.sound_speed.data()),
        pressure_bar(p.pressure_bar.data()),
        theta(p.theta.data()),
        material(p.material.data()) {
    for (std::size_t v = 0; v < 5; ++v) {
      u[v] = p.u[v].data();
      u_new[v] = p.u_new[v].data();
      ubar[v] = p.ubar[v].data();
      flux_bar[v] = p.flux_bar[v].data();
      flux[v] = p.flux[v].data();
      diffusion[v] = p.diffusion[v].data();
    }
  }
};

/// Stage 1 on [lo, hi): pressure and sound speed of u, and the shock switch
/// of T (2-57): 1 at a jump, 0 where the density is linear. Returns how many
/// entries of [lo, hi) within [begin, end) are unphysical (density or
/// pressure not positive, or energy not finite).
template <class Eos>
double state_stage(const Views& a, const Eos& eos, std::size_t w, std::size_t lo, std::size_t hi,
                   std::size_t begin, std::size_t end) {
  const double* rho = a.u[kRho];
  const double *mn = a.u[kMn], *mt1 = a.u[kMt1], *mt2 = a.u[kMt2], *e_total = a.u[kE];
  double bad = 0.0;  // a count; double, so that the loop vectorises at one width
#pragma omp simd reduction(+ : bad)
  for (std::size_t j = lo; j < hi; ++j) {
    const double inv_rho = 1.0 / rho[j];
    const double e = internal_energy_per_mass(inv_rho, mn[j], mt1[j], mt2[j], e_total[j]);
    const double p = eos.pressure(j, rho[j], e);
    a.pressure[j] = p;
    a.sound_speed[j] = eos.sound_speed(j, rho[j], e);
    const bool unphysical = !(rho[j] > 0.0) || !(p > 0.0) || !(std::abs(e_total[j]) <= DBL_MAX);
    bad += unphysical && j >= begin && j < end ? 1.0 : 0.0;
  }
#pragma omp simd
  for (std::size_t j = lo; j < hi; ++j) {
    const double right = std::abs(rho[j + w] - rho[j]);
    const double left = std::abs(rho[j] - rho[j - w]);
    const double sum = right + left;
    a.theta[j] = sum > 0.0 ? std::abs(right - left) / sum : 0.0;
  }
  return bad;
}

/// theta^power, power 1...4: the switch of T (2-57) as it weighs the
/// viscosity (power 1 is the thesis). A higher power keeps the weight 1 at a
/// jump and at an extremum and lowers it where the density only bends.
inline double switch_weight(double theta, int power) {
  const double theta2 = theta * theta;
  return power == 1 ? theta : power == 2 ? theta2 : power == 3 ? theta2 * theta : theta2 * theta2;
}

/// Stage 2 on [lo, hi): the viscous exchange across the face between j and
/// j + w, T (2-56), (2-58).
void diffusion_stage(const Views& a, std::size_t w, std::size_t lo, std::size_t hi, double courant,
                     double viscosity, int switch_power) {
  const double* c = a.sound_speed;
  const double* theta = a.theta;
  const double *u0 = a.u[0], *u1 = a.u[1], *u2 = a.u[2], *u3 = a.u[3], *u4 = a.u[4];
  double *d0 = a.diffusion[0], *d1 = a.diffusion[1], *d2 = a.diffusion[2], *d3 = a.diffusion[3],
         *d4 = a.diffusion[4];
#pragma omp simd
  for (std::size_t j = lo; j < hi; ++j) {
    const double nu = std::min(1.0, courant * std::max(c[j], c[j + w]));
    const double eta = nu * (1.0 - nu);
    const double k =
        0.5 * viscosity * eta * switch_weight(std::max(theta[j], theta[j + w]), switch_power);
    d0[j] = k * (u0[j + w] - u0[j]);
    d1[j] = k * (u1[j + w] - u1[j]);
    d2[j] = k * (u2[j + w] - u2[j]);
    d3[j] = k * (u3[j + w] - u3[j]);
    d4[j] = k * (u4[j + w] - u4[j]);
  }
}

/// Stage 3 on [lo, hi): ubar = u + D_{i+1/2} - D_{i-1/2}, its pressure and
/// its flux along the sweep axis, T (2-50).
template <class Eos>
void viscous_state_stage(const Views& a, const Eos& eos, std::size_t w, std::size_t lo,
                         std::size_t hi) {
  const double *u0 = a.u[0], *u1 = a.u[1], *u2 = a.u[2], *u3 = a.u[3], *u4 = a.u[4];
  const double *d0 = a.diffusion[0], *d1 = a.diffusion[1], *d2 = a.diffusion[2],
               *d3 = a.diffusion[3], *d4 = a.diffusion[4];
  double *b0 = a.ubar[0], *b1 = a.ubar[1], *b2 = a.ubar[2], *b3 = a.ubar[3], *b4 = a.ubar[4];
  double *f0 = a.flux_bar[0], *f1 = a.flux_bar[1], *f2 = a.flux_bar[2], *f3 = a.flux_bar[3],
         *f4 = a.flux_bar[4];
  double* pb = a.pressure_bar;
#pragma omp simd
  for (std::size_t j = lo; j < hi; ++j) {
    const double rho = u0[j] + d0[j] - d0[j - w];
    const double mn = u1[j] + d1[j] - d1[j - w];
    const double mt1 = u2[j] + d2[j] - d2[j - w];
    const double mt2 = u3[j] + d3[j] - d3[j - w];
    const double e_total = u4[j] + d4[j] - d4[j - w];
    b0[j] = rho, b1[j] = mn, b2[j] = mt1, b3[j] = mt2, b4[j] = e_total;
    const double inv_rho = 1.0 / rho;
    const double p = eos.pressure(j, rho, internal_energy_per_mass(inv_rho, mn, mt1, mt2, e_total));
    const double un = mn * inv_rho;
    if constexpr (Eos::kSeveral) pb[j] = p;
    f0[j] = mn;
    f1[j] = mn * un + p;
    f2[j] = mt1 * un;
    f3[j] = mt2 * un;
    f4[j] = (e_total + p) * un;
  }
}

/// Stage 4 on [lo, hi): the Richtmyer half-step state at the face between j
/// and j + w, its pressure and its flux.
template <class Eos>
void half_step_stage(const Views& a, const Eos& eos, std::size_t w, std::size_t lo, std::size_t hi,
                     double courant) {
  const double *b0 = a.ubar[0], *b1 = a.ubar[1], *b2 = a.ubar[2], *b3 = a.ubar[3], *b4 = a.ubar[4];
  const double *g0 = a.flux_bar[0], *g1 = a.flux_bar[1], *g2 = a.flux_bar[2], *g3 = a.flux_bar[3],
               *g4 = a.flux_bar[4];
  double *f0 = a.flux[0], *f1 = a.flux[1], *f2 = a.flux[2], *f3 = a.flux[3], *f4 = a.flux[4];
  const double* pb = a.pressure_bar;
  const std::uint8_t* mat = a.material;
  const double half = 0.5 * courant;
#pragma omp simd
  for (std::size_t j = lo; j < hi; ++j) {
    const double rho = 0.5 * (b0[j] + b0[j + w]) - half * (g0[j + w] - g0[j]);
    const double mn = 0.5 * (b1[j] + b1[j + w]) - half * (g1[j + w] - g1[j]);
    const double mt1 = 0.5 * (b2[j] + b2[j + w]) - half * (g2[j + w] - g2[j]);
    const double mt2 = 0.5 * (b3[j] + b3[j + w]) - half * (g3[j + w] - g3[j]);
    const double e_total = 0.5 * (b4[j] + b4[j + w]) - half * (g4[j + w] - g4[j]);
    const double inv_rho = 1.0 / rho;
    double p = eos.pressure(j, rho, internal_energy_per_mass(inv_rho, mn, mt1, mt2, e_total));
    // Face pressure: the EOS of the material on both sides. Where the face
    // separates two materials (or a mixed cell's own fit), the half-step state
    // blends the two and no single EOS applies; pressure is continuous across
    // a contact, so the face takes the mean of the two cells' pressures.
    if constexpr (Eos::kSeveral)
      if (mat[j] != mat[j + w] || mat[j] == kMixedMaterial) p = 0.5 * (pb[j] + pb[j + w]);
    const double un = mn * inv_rho;
    f0[j] = mn;
    f1[j] = mn * un + p;
    f2[j] = mt1 * un;
    f3[j] = mt2 * un;
    f4[j] = (e_total + p) * un;
  }
}

/// Stage 5 on [lo, hi): the corrector, into u_new. Returns how many updated
/// entries may be unphysical (every mixed cell counts: its test needs its EOS).
template <class Eos>
double corrector_stage(const Views& a, std::size_t w, std::size_t lo, std::size_t hi,
                       double courant) {
  double *u0 = a.u_new[0], *u1 = a.u_new[1], *u2 = a.u_new[2], *u3 = a.u_new[3], *u4 = a.u_new[4];
  const double *b0 = a.ubar[0], *b1 = a.ubar[1], *b2 = a.ubar[2], *b3 = a.ubar[3], *b4 = a.ubar[4];
  const double *f0 = a.flux[0], *f1 = a.flux[1], *f2 = a.flux[2], *f3 = a.flux[3], *f4 = a.flux[4];
  const std::uint8_t* mat = a.material;
  double suspect = 0.0;  // a count; double, so that the loop vectorises at one width
#pragma omp simd reduction(+ : suspect)
  for (std::size_t j = lo; j < hi; ++j) {
    const double rho = b0[j] - courant * (f0[j] - f0[j - w]);
    const double mn = b1[j] - courant * (f1[j] - f1[j - w]);
    const double mt1 = b2[j] - courant * (f2[j] - f2[j - w]);
    const double mt2 = b3[j] - courant * (f3[j] - f3[j - w]);
    const double e_total = b4[j] - courant * (f4[j] - f4[j - w]);
    u0[j] = rho, u1[j] = mn, u2[j] = mt1, u3[j] = mt2, u4[j] = e_total;
    // A division-free screen, conservative by a margin far above round-off:
    // 2 rho E > |m|^2 (1 + 1e-12) implies E - |m|^2 / (2 rho) > 0. Entries it
    // does not clear get the exact test of physical().
    bool bad =
        !(rho > 0.0) || !(2.0 * rho * e_total > (mn * mn + mt1 * mt1 + mt2 * mt2) * (1.0 + 1e-12));
    if constexpr (Eos::kSeveral) bad = bad || mat[j] == kMixedMaterial;
    suspect += bad ? 1.0 : 0.0;
  }
  return suspect;
}

/// The first entry of [lo, hi) whose density or pressure is not positive or
/// whose energy is not finite.
BadCell first_bad_cell(const Views& a, std::size_t w, std::size_t lo, std::size_t hi) {
  const double* rho = a.u[kRho];
  const double* p = a.pressure;
  std::size_t j = lo;
  while (j + 1 < hi && rho[j] > 0.0 && p[j] > 0.0 && std::isfinite(a.u[kE][j])) ++j;
  return BadCell{j / w, j % w, rho[j], p[j]};
}

/// The largest crossing rate (|u_a| + c) / dx_a of entries [lo, hi), with
/// the momenta in x, y, z order as in EulerSolver's grid scan (the same bits
/// for the same cell).
template <class Eos>
double max_crossing_rate(const Views& a, const Eos& eos, std::size_t lo, std::size_t hi,
                         const CrossingTimeRequest& request) {
  const double* rho = a.u_new[kRho];
  const double* e_total = a.u_new[kE];
  const double *mx = a.u_new[request.slot[0]], *my = a.u_new[request.slot[1]],
               *mz = a.u_new[request.slot[2]];
  const auto& inv_dx = request.inv_spacing;
  // An inactive axis counts as one with no signal: rate 0 never wins the max.
  const double on_x = request.active[0], on_y = request.active[1], on_z = request.active[2];
  double rate = 0.0;
#pragma omp simd reduction(max : rate)
  for (std::size_t j = lo; j < hi; ++j) {
    const double inv_rho = 1.0 / rho[j];
    const double e = internal_energy_per_mass(inv_rho, mx[j], my[j], mz[j], e_total[j]);
    const double c = eos.sound_speed(j, rho[j], e);
    const double rx = on_x * crossing_rate(inv_dx[0], mx[j], inv_rho, c);
    const double ry = on_y * crossing_rate(inv_dx[1], my[j], inv_rho, c);
    const double rz = on_z * crossing_rate(inv_dx[2], mz[j], inv_rho, c);
    rate = std::max(rate, std::max(rx, std::max(ry, rz)));
  }
  return rate;
}

/// The whole sweep of the block with the EOS resolved as `eos`: entries
/// [begin, end) are updated.
/// Whether a staged sweep reads its cells from the state as it goes (else
/// the pencil holds them) and writes them back (else they stay in u_new).
struct Traffic {
  bool gather;
  bool scatter;
};

template <class Eos>
std::optional<BadCell> staged_sweep(Pencil& pencil, const BlockTransfer& t, const Eos& eos,
                                    const EntryModels& entries, const SweepStep& step,
                                    const CrossingTimeRequest* crossing, double* min_time,
                                    Traffic traffic) {
  const Views a(pencil);
  const std::size_t w = t.block.lanes;
  const std::size_t first = t.first + kGhost, last = t.last + kGhost;  // pencil positions
  const std::size_t begin = first * w, end = last * w;
  const double courant = step.dt / step.dx;
  // Where each stage has got to. A stage reads the one before up to one
  // position ahead; the state is read kGhost positions ahead of the update.
  std::size_t gathered = first - kGhost;       // positions [first - 3, last + 3)
  std::size_t state_done = begin - 2 * w;      // stage 1: [begin - 2w, end + 2w)
  std::size_t diffusion_done = begin - 2 * w;  // stage 2: [begin - 2w, end + w)
  std::size_t viscous_done = begin - w;        // stage 3: [begin - w, end + w)
  std::size_t half_done = begin - w;           // stage 4: [begin - w, end)
  std::size_t updated = begin;                 // stage 5: [begin, end)
  const std::size_t chunk = std::max(w, kChunkEntries / w * w);
  double suspect = 0.0;
  double rate = 0.0;  // the largest crossing rate of the updated cells, if asked
  while (updated < end) {
    const std::size_t front = std::min(updated + chunk, end);
    if (traffic.gather) gather_rows(t, gathered, front / w + kGhost, pencil);
    gathered = front / w + kGhost;
    // Refuse unphysical cells before they are used.
    if (state_stage(a, eos, w, state_done, front + 2 * w, begin, end) > 0.0)
      return first_bad_cell(a, w, std::max(state_done, begin), std::min(front + 2 * w, end));
    state_done = front + 2 * w;
    diffusion_stage(a, w, diffusion_done, front + w, courant, step.viscosity, step.switch_power);
    diffusion_done = front + w;
    viscous_state_stage(a, eos, w, viscous_done, front + w);
    viscous_done = front + w;
    half_step_stage(a, eos, w, half_done, front, courant);
    half_done = front;
    suspect += corrector_stage<Eos>(a, w, updated, front, courant);
    if (crossing != nullptr)
      rate = std::max(rate, max_crossing_rate(a, eos, updated, front, *crossing));
    if (traffic.scatter) scatter_rows(pencil, t, updated / w, front / w);
    updated = front;
  }
  bool repaired = false;
  if (suspect > 0.0 && t.only_material)
    gather_materials(t, pencil);  // the fallback reads each entry's material
  if (suspect > 0.0)
    for (int pass = 0;
         pass < kFallbackPasses && repair_unphysical_cells(pencil, entries, w, begin, end, courant);
         ++pass)
      repaired = true;
  if (repaired) {
    if (traffic.scatter) scatter_rows(pencil, t, first, last);
    if (crossing != nullptr) rate = max_crossing_rate(a, eos, begin, end, *crossing);
  }
  if (crossing != nullptr) *min_time = std::min(*min_time, 1.0 / rate);
  return std::nullopt;
}

/// The material of the block's cells if they share one (no mixed cell) on
/// the stencil of t, gathering the materials first unless the grid has one.
std::optional<std::uint8_t> block_material(Pencil& pencil, const BlockTransfer& t) {
  if (t.only_material) return t.only_material;
  gather_materials(t, pencil);
  const std::size_t w = t.block.lanes;
  const std::uint8_t* lo = pencil.material.data() + t.first * w;  // position first - kGhost
  const std::uint8_t* hi = pencil.material.data() + (t.last + 2 * kGhost) * w;
  const std::uint8_t one = *lo;
  if (one == kMixedMaterial || !std::all_of(lo, hi, [one](std::uint8_t m) { return m == one; }))
    return std::nullopt;
  return one;
}

/// What crossed the ends of t's range: dt F - dx D at the faces below its
/// first cell and above its last, and below cell t.tap if set (written, not added).
void add_end_fluxes(const Pencil& pencil, const BlockTransfer& t, const SweepStep& step,
                    EndFluxes& ends) {
  const std::size_t w = t.block.lanes;
  const std::size_t begin = (t.first + kGhost) * w, end = (t.last + kGhost) * w;
  const std::size_t tap = (t.tap + kGhost) * w;
  for (std::size_t v = 0; v < 5; ++v) {
    const double* f = pencil.flux[v].data();
    const double* d = pencil.diffusion[v].data();
    for (std::size_t lane = 0; lane < w; ++lane) {
      ends.lower[lane][v] = step.dt * f[begin - w + lane] - step.dx * d[begin - w + lane];
      ends.upper[lane][v] = step.dt * f[end - w + lane] - step.dx * d[end - w + lane];
      if (t.tap != 0)
        ends.tapped[lane][v] = step.dt * f[tap - w + lane] - step.dx * d[tap - w + lane];
    }
  }
}

/// Runs body(eos) with the block's EOS resolved: one model inlined, or each
/// entry's own.
template <class Body>
auto with_block_eos(const Pencil& pencil, std::optional<std::uint8_t> material,
                    std::span<const eos::AnyEos> models, const Body& body) {
  const EntryModels entries{models, pencil.material.data(), pencil.mix_gamma.data(),
                            pencil.mix_pinf.data()};
  if (!material) return body(entries, entries);
  return std::visit(
      [&](const auto& model) {
        using Model = std::decay_t<decltype(model)>;
        return body(OneModel<Model>{model}, entries);
      },
      models[*material]);
}

}  // namespace

namespace MPFD_SWEEP_ISA {

std::optional<BadCell> sweep_block(Pencil& pencil, const BlockTransfer& t, const SweepStep& step,
                                   std::span<const eos::AnyEos> models, EndFluxes& ends,
                                   const CrossingTimeRequest* crossing, double* min_crossing_time) {
  const auto bad = with_block_eos(
      pencil, block_material(pencil, t), models, [&](const auto& eos, const EntryModels& entries) {
        return staged_sweep(pencil, t, eos, entries, step, crossing, min_crossing_time,
                            {.gather = true, .scatter = true});
      });
  if (bad) return bad;
  add_end_fluxes(pencil, t, step, ends);
  return std::nullopt;
}

std::optional<BadCell> sweep_block_twice(Pencil& pencil, const BlockTransfer& t1,
                                         const BlockTransfer& t2, const SweepStep& step,
                                         std::span<const eos::AnyEos> models,
                                         std::array<EndFluxes, 2>& ends,
                                         const CrossingTimeRequest* crossing,
                                         double* min_crossing_time) {
  const std::size_t w = t2.block.lanes;
  // t2's stencil holds t1's, and what lies outside t1 the first sweep leaves.
  gather_rows(t2, t2.first, t2.last + 2 * kGhost, pencil);
  return with_block_eos(
      pencil, block_material(pencil, t2), models,
      [&](const auto& eos, const EntryModels& entries) -> std::optional<BadCell> {
        if (auto bad = staged_sweep(pencil, t1, eos, entries, step, nullptr, nullptr,
                                    {.gather = false, .scatter = false}))
          return bad;
        add_end_fluxes(pencil, t1, step, ends[0]);
        for (std::size_t v = 0; v < 5; ++v)
          std::copy(pencil.u_new[v].begin() + static_cast<std::ptrdiff_t>((t1.first + kGhost) * w),
                    pencil.u_new[v].begin() + static_cast<std::ptrdiff_t>((t1.last + kGhost) * w),
                    pencil.u[v].begin() + static_cast<std::ptrdiff_t>((t1.first + kGhost) * w));
        remake_ghosts(t2, pencil);  // the mirrors of cells the first sweep moved
        if (auto bad = staged_sweep(pencil, t2, eos, entries, step, crossing, min_crossing_time,
                                    {.gather = false, .scatter = true}))
          return bad;
        add_end_fluxes(pencil, t2, step, ends[1]);
        return std::nullopt;
      });
}

}  // namespace MPFD_SWEEP_ISA
}  // namespace mpfd::fdm

// A unity batch may compile other sources after this one.
#undef MPFD_SWEEP_ISA
