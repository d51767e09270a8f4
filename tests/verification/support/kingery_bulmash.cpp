#include "tests/verification/support/kingery_bulmash.hpp"

#include <array>
#include <cmath>
#include <span>

#include "common/core/require.hpp"

namespace mpfd::verification {
namespace {

constexpr double kMinScaledDistance = 0.5;
constexpr double kMaxScaledDistance = 40.0;

constexpr std::array<double, 2> kPressureU{-0.214362789151, 1.35034249993};
constexpr std::array<double, 9> kPressureC{2.611368669,       -1.69012801396,    0.00804973591951,
                                           0.336743114941,    -0.00516226351334, -0.0809228619888,
                                           -0.00478507266747, 0.00793030472242,  0.0007684469735};
constexpr std::array<double, 2> kArrivalU{-0.253273111999, 1.37407043777};
constexpr std::array<double, 8> kArrivalC{0.0720707787637,  1.36456871214,    -0.0570035692784,
                                          -0.182832224796,  0.0118851436014,  0.0432648687627,
                                          -0.0007997367834, -0.00436073555033};

// 10^(sum_i C_i U^i), U = K0 + K1 log10 Z (Horner).
double kb_fit(double z, const std::array<double, 2>& k, std::span<const double> c) {
  require(z >= kMinScaledDistance && z <= kMaxScaledDistance, "Kingery-Bulmash",
          "scaled distance Z [m/kg^(1/3)]", z, "in [0.5, 40]");
  const double u = k[0] + k[1] * std::log10(z);
  double y = 0.0;
  for (auto it = c.rbegin(); it != c.rend(); ++it) y = y * u + *it;
  return std::pow(10.0, y);
}

}  // namespace

double kingery_bulmash_overpressure(double scaled_distance) {
  return 1e3 * kb_fit(scaled_distance, kPressureU, kPressureC);  // kPa -> Pa
}

double kingery_bulmash_scaled_arrival_time(double scaled_distance) {
  return 1e-3 * kb_fit(scaled_distance, kArrivalU, kArrivalC);  // ms -> s
}

FreeAirBlast kingery_bulmash_free_air(double charge_mass, double distance) {
  require(charge_mass > 0.0, "Kingery-Bulmash", "charge mass W [kg]", charge_mass, "> 0");
  require(distance > 0.0, "Kingery-Bulmash", "distance R [m]", distance, "> 0");
  const double cube_root = std::cbrt(charge_mass);
  const double z = distance / cube_root;
  return {z, kingery_bulmash_overpressure(z), cube_root * kingery_bulmash_scaled_arrival_time(z)};
}

}  // namespace mpfd::verification
