"""The V4 model's own converged peak overpressure: the 13.05 g JWL TNT sphere in
ideal-gas air (gamma 1.4), program burn from the centre, from the 1D Lagrangian
reference (lagrangian_1d.py, Delta r = 0.0625 mm; the two finest grids differ by
<= 0.5 %; docs/afdmp.md "Converged 1D model reference"). A solver of this model can
at best reach these values, whatever its grid: the distance of a run from them is
its own discretisation error."""
import math

# Z [m/kg^(1/3)] -> peak incident overpressure [Pa]
PEAK_OVERPRESSURE = {0.5: 3822e3, 0.75: 1790e3, 1.0: 952.9e3, 1.5: 340.4e3, 2.0: 171.4e3,
                     3.0: 73.38e3, 4.0: 43.45e3, 5.0: 29.91e3}


def overpressure(z, tolerance=2e-3):
    """The converged peak at a tabulated Z (within `tolerance` relative); NaN elsewhere."""
    for tabulated, peak in PEAK_OVERPRESSURE.items():
        if abs(z / tabulated - 1) <= tolerance:
            return peak
    return math.nan
