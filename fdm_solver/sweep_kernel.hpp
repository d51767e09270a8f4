#pragma once
// One 1D sweep of the split Euler equations over a block of pencils,
// T (2-53)-(2-58):
//  1. pressure and sound speed from the EOS of each cell's material;
//  2. adaptive artificial viscosity, T (2-56)-(2-58), in conservative form:
//       Ubar_i = U_i + D_{i+1/2} - D_{i-1/2},
//       D_{i+1/2} = kappa/2 eta theta_{i+1/2} (U_{i+1} - U_i),
//       theta_{i+1/2} = max(theta_i, theta_{i+1}),  eta = nu (1 - nu), nu = c dt/dx.
//     (2-56) as printed, theta_i (U_{i+1} - 2U_i + U_{i-1}) / 2, does not
//     conserve mass or energy when theta varies; the face form does, and
//     equals it where theta is uniform.
//  3. two-step Richtmyer Lax-Wendroff (METHOD.md §2: (2-51) as printed drops
//     the flux Jacobian), second order in space and time:
//       U_{i+1/2} = (Ubar_i + Ubar_{i+1})/2 - dt/(2dx) (F(Ubar_{i+1}) - F(Ubar_i))
//       U_i^new   = Ubar_i - dt/dx (F(U_{i+1/2}) - F(U_{i-1/2})).
// Pure functions of the pencil: no allocation, no I/O, no globals.

#include <array>
#include <cstddef>
#include <optional>
#include <span>

#include "common/eos/any_eos.hpp"
#include "fdm_solver/pencil.hpp"

namespace mpfd::fdm {

struct SweepStep {
  double dt;         ///< time step of this sweep [s]
  double dx;         ///< cell size along the sweep [m]
  double viscosity;  ///< kappa, scales eta of T (2-58); 0 switches it off [-]
};

/// A cell whose state is not physical (density or pressure not > 0, or not finite).
struct BadCell {
  std::size_t position;  ///< position along the pencil
  std::size_t lane;      ///< lane of the block
  double density;
  double pressure;
};

/// What crossed the two ends of the updated range during the sweep, summed
/// over the lanes, per unit face area: dt F - dx D (kg/m^2, kg/(m s), J/m^2).
struct EndFluxes {
  std::array<double, 5> lower{};
  std::array<double, 5> upper{};
};

/// The equation of state of every buffer entry: the model of its material,
/// or its own stiffened gas where the material is kMixedMaterial.
struct EosView {
  std::span<const eos::AnyEos> models;
  const std::uint8_t* material;
  const double* mix_gamma;
  const double* mix_pinf;
};

/// Updates positions [first, last) of every lane in place (position = cell +
/// kGhost). The pencil must hold valid states on [first - 3, last + 3).
/// Returns the first unphysical cell met in [first, last) before the
/// update, if any (the pencil is then left unchanged).
std::optional<BadCell> sweep_pencil(Pencil& pencil, std::size_t lanes, std::size_t first,
                                    std::size_t last, const SweepStep& step,
                                    std::span<const eos::AnyEos> models, EndFluxes& ends);

/// Pressure of buffer entries [first, last) from the rotated state, and their
/// sound speed too unless `sound_speed` is null.
void compute_pressure(const EosView& eos, const std::array<std::vector<double>, 5>& u,
                      double* pressure, double* sound_speed, std::size_t first, std::size_t last);

}  // namespace mpfd::fdm
