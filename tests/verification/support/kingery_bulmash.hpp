#pragma once
// Kingery-Bulmash free-air (spherical) TNT blast parameters: incident peak
// overpressure and shock arrival time vs scaled distance Z = R / W^(1/3).
// Source: C. N. Kingery and G. Bulmash, "Airblast Parameters from TNT
// Spherical Air Burst and Hemispherical Surface Burst", ARBRL-TR-02555
// (1984), the fits behind UFC 3-340-02 (2008) Fig. 2-7, as tabulated
// (metric) in ARL-TR-1310 (CONWEP), App. A. Each is a polynomial in
//   U = K0 + K1 log10(Z),   log10(Y) = sum_i C_i U^i
// (base-10 logarithms, as KB publish them; Z in m/kg^(1/3)):
//   incident overpressure P_so [kPa], spherical free air, 0.0531 <= Z <= 40:
//     K0 = -0.214362789151, K1 = 1.35034249993
//     C = 2.611368669, -1.69012801396, 0.00804973591951, 0.336743114941,
//         -0.00516226351334, -0.0809228619888, -0.00478507266747,
//         0.00793030472242, 0.0007684469735
//   arrival time t_a / W^(1/3) [ms/kg^(1/3)], spherical free air, 0.0531 <= Z <= 40:
//     K0 = -0.253273111999, K1 = 1.37407043777
//     C = 0.0720707787637, 1.36456871214, -0.0570035692784, -0.182832224796,
//         0.0118851436014, 0.0432648687627, -0.0007997367834, -0.00436073555033
// This class serves the verification range 0.5 <= Z <= 40 (V4); outside it
// throws mpfd::Error. Results in SI (Pa, s).

namespace mpfd::verification {

struct FreeAirBlast {
  double scaled_distance;  ///< Z [m/kg^(1/3)]
  double overpressure;     ///< P_so [Pa]
  double arrival_time;     ///< t_a [s] for the given charge mass
};

/// P_so [Pa] at scaled distance Z [m/kg^(1/3)], 0.5 <= Z <= 40.
[[nodiscard]] double kingery_bulmash_overpressure(double scaled_distance);

/// t_a / W^(1/3) [s/kg^(1/3)] at scaled distance Z, 0.5 <= Z <= 40.
[[nodiscard]] double kingery_bulmash_scaled_arrival_time(double scaled_distance);

/// Both at distance R [m] from a W [kg] TNT sphere.
[[nodiscard]] FreeAirBlast kingery_bulmash_free_air(double charge_mass, double distance);

}  // namespace mpfd::verification
