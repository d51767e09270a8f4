"""Kingery-Bulmash free-air spherical TNT fits (ARBRL-TR-02555, UFC 3-340-02
Fig. 2-7; the same coefficients as tests/verification/support/kingery_bulmash.cpp).
log10(Y) = sum_i C_i U^i, U = K0 + K1 log10(Z), Z = R / W^(1/3) [m/kg^(1/3)]."""
import math

_PRESSURE_K = (-0.214362789151, 1.35034249993)
_PRESSURE_C = (2.611368669, -1.69012801396, 0.00804973591951, 0.336743114941,
               -0.00516226351334, -0.0809228619888, -0.00478507266747,
               0.00793030472242, 0.0007684469735)
_ARRIVAL_K = (-0.253273111999, 1.37407043777)
_ARRIVAL_C = (0.0720707787637, 1.36456871214, -0.0570035692784, -0.182832224796,
              0.0118851436014, 0.0432648687627, -0.0007997367834, -0.00436073555033)
Z_MIN, Z_MAX = 0.5, 40.0


def _fit(z, k, c):
    if not Z_MIN <= z <= Z_MAX:
        raise ValueError(f"Kingery-Bulmash: Z = {z} m/kg^(1/3) outside [0.5, 40]")
    u = k[0] + k[1] * math.log10(z)
    return 10.0 ** sum(ci * u ** i for i, ci in enumerate(c))


def overpressure(z):
    """Incident peak overpressure P_so [Pa]."""
    return 1e3 * _fit(z, _PRESSURE_K, _PRESSURE_C)


def arrival_time(charge_mass, distance):
    """Shock arrival time [s] at R [m] from W [kg] TNT."""
    w3 = charge_mass ** (1.0 / 3.0)
    return 1e-3 * w3 * _fit(distance / w3, _ARRIVAL_K, _ARRIVAL_C)
