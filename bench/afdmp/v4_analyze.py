#!/usr/bin/python3
"""V4 gauge readings of one `coupler run` against Kingery-Bulmash.

v4_analyze.py RUN_DIR SCENE.yaml [CHARGE_MASS_KG | auto]   (default 0.01304 kg,
the thesis's 20 mm cube; the equal-mass sphere holds 13.05 g). auto: the TNT
mass the run actually holds (charge_mass_of_run): the 3D MPM start fills the
charge with particles on the grid, so a sphere or a cube whose side is no
multiple of h holds another mass (the sphere 11.41 / 12.23 / 13.53 g on 25^3 /
50^3 / 80^3, the cube 10.75 g on 80^3).

Per gauge: R = |position| (the charge sits at the origin of the octant), Z =
R / W^(1/3); peak overpressure = max(p) - p(t = 0); arrival = the first time
p - p(0) exceeds 10 % of that peak (linear interpolation between samples).
Gauges with Z < 0.5 (outside the Kingery-Bulmash range) are printed without
a reference. ahead_drop = min(p before arrival) / p(0) - 1: the ambient air
ahead of the shock should stay at p(0); with the 3D MPM start it does not near
the outflow faces (air leaves through them in the MPM phase). Output: one CSV
row per gauge on stdout.
"""
import csv
import json
import math
import os
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import v4_kb  # noqa: E402

THESIS_CUBE_MASS = 0.01304  # kg: 20 mm cube of 1630 kg/m^3 TNT (T §3.4.3)


def charge_mass_of_run(run_dir, scene_file):
    """Full-charge TNT mass [kg] from the first handoff's FDM totals: the octant's
    mass less the ambient air it would hold without the charge, times 8 (three
    symmetry planes through the charge centre)."""
    scene = yaml.safe_load(open(scene_file))
    handoff = json.load(open(os.path.join(run_dir, "summary.json")))["details"]["afdmp"]["handoffs"][0]
    lower, upper = scene["domain"]["lower"], scene["domain"]["upper"]
    volume = math.prod(u - l for l, u in zip(lower, upper))
    rho_air = scene["initial"]["density"]
    rho_tnt = scene["materials"]["tnt"]["eos"]["rho0"]
    octant = (handoff["solver_totals"]["mass"] - rho_air * volume) / (1 - rho_air / rho_tnt)
    return 8 * octant


def gauge_readings(run_dir, scene_file):
    """[(name, R, peak_overpressure, arrival, ahead_drop)] of every gauge of the scene
    (R = |position|; in a 1D spherical scene, R = position x)."""
    scene = yaml.safe_load(open(scene_file))
    radial = scene["domain"].get("geometry") == "spherical"
    rows = list(csv.reader(open(os.path.join(run_dir, "gauges.csv"))))
    header, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
    readings = []
    for gauge in scene["gauges"]:
        name = gauge["name"]
        j = header.index(f"{name}.pressure[Pa]")
        t, p = [r[0] for r in data], [r[j] for r in data]
        peak = max(p) - p[0]
        threshold = p[0] + 0.1 * peak
        arrival, ahead = math.nan, p[0]
        for k in range(1, len(p)):
            if p[k] > threshold:
                arrival = t[k - 1] + (threshold - p[k - 1]) / (p[k] - p[k - 1]) * (t[k] - t[k - 1])
                break
            ahead = min(ahead, p[k])
        r = gauge["position"][0] if radial else math.hypot(*gauge["position"])
        readings.append((name, r, peak, arrival, ahead / p[0] - 1))
    return readings


def compare(run_dir, scene_file, charge_mass=THESIS_CUBE_MASS):
    """Rows: name, R, Z, peak, kb_peak, peak_error, arrival, kb_arrival, arrival_error,
    ahead_drop (errors relative, signed; KB columns NaN for Z < 0.5)."""
    w3 = charge_mass ** (1.0 / 3.0)
    out = []
    for name, r, peak, arrival, ahead_drop in gauge_readings(run_dir, scene_file):
        z = r / w3
        if z >= v4_kb.Z_MIN:
            kb_peak, kb_arrival = v4_kb.overpressure(z), v4_kb.arrival_time(charge_mass, r)
        else:
            kb_peak = kb_arrival = math.nan
        out.append({"gauge": name, "R_m": r, "Z": z, "peak_Pa": peak, "kb_peak_Pa": kb_peak,
                     "peak_error": peak / kb_peak - 1, "arrival_s": arrival,
                     "kb_arrival_s": kb_arrival, "arrival_error": arrival / kb_arrival - 1,
                     "ahead_drop": ahead_drop})
    return out


def main():
    mass = sys.argv[3] if len(sys.argv) > 3 else THESIS_CUBE_MASS
    mass = charge_mass_of_run(sys.argv[1], sys.argv[2]) if mass == "auto" else float(mass)
    rows = compare(sys.argv[1], sys.argv[2], mass)
    writer = csv.DictWriter(sys.stdout, fieldnames=list(rows[0]))
    writer.writeheader()
    for row in sorted(rows, key=lambda r: r["R_m"]):
        writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()})


if __name__ == "__main__":
    main()
