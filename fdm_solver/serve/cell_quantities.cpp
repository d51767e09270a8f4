#include "fdm_solver/serve/cell_quantities.hpp"

#include "common/core/error.hpp"

namespace mpfd::fdm {
namespace {

constexpr std::array<QuantityInfo, 5> kQuantities{{
    {"rho", 1, "kg/m^3", true},
    {"momentum", 3, "kg/(m^2*s)", true},
    {"E", 1, "J/m^3", true},
    {"pressure", 1, "Pa", false},
    {"velocity", 3, "m/s", false},
}};

}  // namespace

const QuantityInfo& info(Quantity q) {
  return kQuantities[static_cast<std::size_t>(q)];
}

std::optional<Quantity> find_quantity(std::string_view name) {
  for (std::size_t i = 0; i < kQuantities.size(); ++i)
    if (kQuantities[i].name == name) return static_cast<Quantity>(i);
  return std::nullopt;
}

std::string quantity_names() {
  std::string names;
  for (const auto& q : kQuantities) names += (names.empty() ? "" : ", ") + std::string(q.name);
  return names;
}

std::vector<double>& conserved_array(EulerState& state, Quantity q, std::size_t c) {
  switch (q) {
    case Quantity::rho:
      return state.u[kDensity];
    case Quantity::momentum:
      return state.u[kMomentumX + c];
    case Quantity::energy:
      return state.u[kEnergy];
    case Quantity::pressure:
    case Quantity::velocity:
      break;
  }
  fail_invariant("info(q).writable", "'" + std::string(info(q).name) + "' is not conserved",
                 __FILE__, __LINE__, __func__);
}

}  // namespace mpfd::fdm
