#include "fdm_solver/tracer/mixed_cell_closure.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <variant>

#include "fdm_solver/tracer/bracketed_newton.hpp"
#include "fdm_solver/tracer/energy_split.hpp"

namespace mpfd::fdm {
namespace {

constexpr double kTolerance = 1e-12;  // on |f_1 - f_2| / max(|f_1|, |f_2|)
constexpr int kMaxIterations = 60;
constexpr int kScanOctaves = 40;  // geometric samples per half of [0, 1] in y_1

/// Whose mass fraction the unknown w is: material 1 (y_1 = w) or 2 (y_2 = w).
enum class Side { first, second };

template <class Eos1, class Eos2>
struct Equilibrium {
  const Eos1& eos1;
  const Eos2& eos2;
  const MixedCellInput& in;
  EnergyPair split;  // e_1, e_2 before any rescaling

  [[nodiscard]] double theta2() const { return 1.0 - in.theta1; }  // T (3-27)

  /// Densities and energies at mass fractions y1 + y2 = 1 (pressure not set).
  [[nodiscard]] MixedCellState at(double y1, double y2) const {
    MixedCellState s;
    s.rho1 = y1 * in.rho_c / in.theta1;  // T (3-28): theta_1 rho_1 + theta_2 rho_2 = rho_c
    s.rho2 = y2 * in.rho_c / theta2();
    const double k = in.cell_energy ? energy_scale(y1, y2, split, *in.cell_energy) : 1.0;
    s.e1 = k * split.first;
    s.e2 = k * split.second;
    return s;
  }
  [[nodiscard]] MixedCellState at(Side side, double w) const {
    return side == Side::first ? at(w, 1.0 - w) : at(1.0 - w, w);
  }
  [[nodiscard]] Residual residual(const MixedCellState& s) const {
    const double p1 = eos1.pressure(s.rho1, s.e1);  // T (3-24)
    const double p2 = eos2.pressure(s.rho2, s.e2);
    return {p1 - p2, std::max(std::abs(p1), std::abs(p2))};
  }
  [[nodiscard]] MixedCellState finish(MixedCellState s, int iterations,
                                      ClosureStatus status) const {
    s.pressure = in.theta1 * eos1.pressure(s.rho1, s.e1) + theta2() * eos2.pressure(s.rho2, s.e2);
    s.iterations = iterations;
    s.status = status;
    return s;
  }
  /// rho_1 = rho_2 = rho_c, y_r = theta_r.
  [[nodiscard]] MixedCellState fallback() const {
    const double t1 = std::clamp(in.theta1, 0.0, 1.0);
    MixedCellState s;
    s.rho1 = s.rho2 = in.rho_c;
    const double k = in.cell_energy ? energy_scale(t1, 1.0 - t1, split, *in.cell_energy) : 1.0;
    s.e1 = k * split.first;
    s.e2 = k * split.second;
    s.pressure = t1 * eos1.pressure(s.rho1, s.e1) + (1.0 - t1) * eos2.pressure(s.rho2, s.e2);
    s.status = ClosureStatus::fallback;
    return s;
  }
};

struct Bracket {
  Side side;
  double lo;
  double hi;
  double f_lo;
};

/// The first sign change of f_1 - f_2 along y_1 in [0, 1]; an exact zero at a
/// sample comes back as a bracket of width 0.
template <class E>
std::optional<Bracket> find_bracket(const E& eq) {
  const auto g = [&](Side side, double w) { return eq.residual(eq.at(side, w)).value; };
  const double at0 = g(Side::first, 0.0);
  const double mid = g(Side::first, 0.5);
  const double at1 = g(Side::second, 0.0);
  if (at0 == 0.0) return Bracket{Side::first, 0.0, 0.0, 0.0};
  if (mid == 0.0) return Bracket{Side::first, 0.5, 0.5, 0.0};
  if (at1 == 0.0) return Bracket{Side::second, 0.0, 0.0, 0.0};
  if ((at0 < 0.0) != (mid < 0.0)) return Bracket{Side::first, 0.0, 0.5, at0};
  if ((at1 < 0.0) != (mid < 0.0)) return Bracket{Side::second, 0.0, 0.5, at1};
  // Geometric samples w = 2^-k / 2 find a root within any factor of 2 in mass
  // fraction, down to 5e-13, e.g. products over-compressed into a sliver of
  // the cell, where JWL's p(rho) turns down (p_ref -> -inf as V -> 0).
  const auto octave = [](int k) { return 0.5 * std::ldexp(1.0, -k); };
  double w_prev = 0.0;
  double f_prev = at0;
  for (int k = kScanOctaves; k >= 0; --k) {  // y_1 from 0 up to 1/2
    const double w = octave(k);
    const double f = g(Side::first, w);
    if (f == 0.0) return Bracket{Side::first, w, w, 0.0};
    if ((f < 0.0) != (f_prev < 0.0)) return Bracket{Side::first, w_prev, w, f_prev};
    w_prev = w;
    f_prev = f;
  }
  for (int k = 0; k <= kScanOctaves; ++k) {  // y_1 from 1/2 up to 1
    const double w = octave(k);
    const double f = g(Side::second, w);
    if (f == 0.0) return Bracket{Side::second, w, w, 0.0};
    if ((f < 0.0) != (f_prev < 0.0)) return Bracket{Side::second, w, w_prev, f};
    w_prev = w;
    f_prev = f;
  }
  if ((at1 < 0.0) != (f_prev < 0.0)) return Bracket{Side::second, 0.0, w_prev, at1};
  return std::nullopt;
}

template <class Eos1, class Eos2>
MixedCellState close(const Eos1& eos1, const Eos2& eos2, const MixedCellInput& in) {
  EnergyPair split{in.e1, in.e2};
  if (in.cell_energy) split = energies_to_rescale(split, *in.cell_energy);
  const Equilibrium<Eos1, Eos2> eq{eos1, eos2, in, split};
  const bool finite = std::isfinite(in.rho_c) && std::isfinite(in.e1) && std::isfinite(in.e2) &&
                      std::isfinite(in.cell_energy.value_or(0.0));
  if (!finite || !(in.theta1 > 0.0 && in.theta1 < 1.0) || !(in.rho_c > 0.0)) return eq.fallback();
  const std::optional<Bracket> b = find_bracket(eq);
  if (!b) return eq.fallback();
  if (b->lo == b->hi) return eq.finish(eq.at(b->side, b->lo), 0, ClosureStatus::converged);
  const RootResult root = bracketed_newton([&](double w) { return eq.residual(eq.at(b->side, w)); },
                                           b->lo, b->hi, b->f_lo, kTolerance, kMaxIterations);
  return eq.finish(eq.at(b->side, root.x), root.iterations,
                   root.converged ? ClosureStatus::converged : ClosureStatus::iteration_limit);
}

}  // namespace

MixedCellState close_mixed_cell(const eos::AnyEos& eos1, const eos::AnyEos& eos2,
                                const MixedCellInput& in) noexcept {
  return std::visit([&](const auto& a, const auto& b) { return close(a, b, in); }, eos1, eos2);
}

}  // namespace mpfd::fdm
