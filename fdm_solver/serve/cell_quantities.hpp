#pragma once
// The cell quantities the FDM solver exchanges (proto/README.md §3): the
// conserved `rho`, `momentum` (rho u, 3 components) and `E` (total energy per
// volume), which a coupler may set or add to, and the derived `pressure` and
// `velocity`, which it may only read. Derived values use the arithmetic of
// PrimitiveFields, so they equal the snapshots' values bit for bit.

#include <array>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/eos/any_eos.hpp"
#include "fdm_solver/cell_eos.hpp"
#include "fdm_solver/euler_state.hpp"

namespace mpfd::fdm {

enum class Quantity { rho, momentum, energy, pressure, velocity };

struct QuantityInfo {
  std::string_view name;   ///< protocol name
  std::size_t components;  ///< 1, or 3 for vectors ([n, 3], components x, y, z last)
  std::string_view units;
  bool writable;  ///< a coupler may ApplyRegion it
};

[[nodiscard]] const QuantityInfo& info(Quantity q);
/// The quantity called `name`, or nothing.
[[nodiscard]] std::optional<Quantity> find_quantity(std::string_view name);
/// Every name, for error messages: "rho, momentum, E, pressure, velocity".
[[nodiscard]] std::string quantity_names();

/// Primitive values of one cell: u = (rho u) / rho, e = E / rho - |u|^2 / 2,
/// p = p(rho, e) from the cell's own EOS (cell_eos.hpp; T 2-49, 2-50).
struct CellPrimitives {
  double rho;
  std::array<double, 3> velocity;
  double pressure;
};

[[nodiscard]] inline CellPrimitives cell_primitives(const EulerState& state,
                                                    const std::vector<eos::AnyEos>& eos,
                                                    std::size_t cell) {
  const auto& u = state.u;
  const double rho = u[kDensity][cell];
  const std::array<double, 3> v{u[kMomentumX][cell] / rho, u[kMomentumY][cell] / rho,
                                u[kMomentumZ][cell] / rho};
  const double kinetic = 0.5 * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  const double e = u[kEnergy][cell] / rho - kinetic;
  return {rho, v, cell_pressure(state, eos, cell, rho, e)};
}

/// The info(q).components values of quantity `q` in `cell`, into `out`.
inline void cell_values(const EulerState& state, const std::vector<eos::AnyEos>& eos, Quantity q,
                        std::size_t cell, std::array<double, 3>& out) {
  const auto& u = state.u;
  switch (q) {
    case Quantity::rho:
      out[0] = u[kDensity][cell];
      return;
    case Quantity::momentum:
      out = {u[kMomentumX][cell], u[kMomentumY][cell], u[kMomentumZ][cell]};
      return;
    case Quantity::energy:
      out[0] = u[kEnergy][cell];
      return;
    case Quantity::pressure:
      out[0] = cell_primitives(state, eos, cell).pressure;
      return;
    case Quantity::velocity:
      out = cell_primitives(state, eos, cell).velocity;
      return;
  }
}

/// The conserved array that holds component `c` of a writable quantity.
[[nodiscard]] std::vector<double>& conserved_array(EulerState& state, Quantity q, std::size_t c);

}  // namespace mpfd::fdm
