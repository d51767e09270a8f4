#pragma once
// Cole's similitude law for the peak pressure of an underwater TNT
// explosion (R. H. Cole, "Underwater Explosions", Princeton University
// Press 1948, pp. 31-70; S ref. [15], S Fig. 3 and Table 1):
//   P_m = 52.4 (W^(1/3) / R)^1.13  MPa,   W in kg TNT, R in m.
// Result in Pa.

namespace mpfd::verification {

/// P_m [Pa] at distance R [m] from W [kg] of TNT; mpfd::Error unless both > 0.
[[nodiscard]] double cole_peak_pressure(double charge_mass, double distance);

}  // namespace mpfd::verification
