#!/usr/bin/python3
"""Extreme deformation: the Taylor bar at twice its test speed (454 m/s), a
steel plate perforated by a TNT blast (2D MPM, Johnson-Cook with failure), and
particles crossing many cells per step (thin air, 1e-3 kg/m^3, next to
detonation products at 8.4 GPa; a steel rod at 6 km/s into a plate at CFL 0.5
and 1). Each must stay bounded or stop
with a named error.

Usage: extreme_runs.py BUILD OUT [--cases a,b] [--check] [--fast]
Writes OUT/extreme_runs.csv. --fast: coarser grids and shorter ends (the CI
subset). --check exits 1 on a nan, crash, hang or unbounded outcome of a
checked case.
"""
import argparse
import copy
import os
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_stability_runs_common as common  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
AIR = {"eos": {"type": "ideal_gas", "gamma": 1.4}}
TNT = {"eos": {"type": "jwl", "rho0": 1630, "A": 3.712e11, "B": 3.21e9, "R1": 4.15,
               "R2": 0.95, "omega": 0.3, "E0": 6.993e9}}
STEEL = {"eos": {"type": "mie_gruneisen", "rho0": 7830, "C0": 4569, "S": 1.49, "gamma0": 2.17},
         "strength": {"type": "johnson_cook", "A": 7.92e8, "B": 5.10e8, "n": 0.26, "C": 0.014,
                      "m": 1.03, "T_melt": 1793, "specific_heat": 477,
                      "shear_modulus": 7.75e10, "failure_strain": 0.3}}
AIR_STATE = {"density": 1.225, "specific_internal_energy": 2.0685e5}
TNT_STATE = {"density": 1630, "specific_internal_energy": 4.2902e6}   # p = 8.38 GPa


def box(lower, upper):
    return {"box": {"lower": lower, "upper": upper}}


def taylor_bar(fast):
    with open(os.path.join(ROOT, "configs", "taylor_bar.yaml")) as f:
        scene = yaml.safe_load(f)
    scene["name"] = "extreme_taylor_bar_2x"
    scene["bodies"][0]["velocity"] = [0, 0, -454.0]
    if fast:  # h = 0.8 mm as the CI Taylor bar, half its end time
        scene["domain"]["cells"] = [12, 12, 42]
        scene["time"]["end"] = 4.0e-5
    scene["output"]["interval"] = scene["time"]["end"] / 4
    return scene


def plate_blast(fast):
    n = 40 if fast else 80
    h = 0.2 / n
    return {
        "name": "extreme_plate_blast",
        "time": {"end": 3.0e-5 if fast else 1.0e-4, "cfl": 0.5},
        "domain": {"lower": [0, 0, 0], "upper": [0.2, 0.2, h], "cells": [n, n, 1]},
        "materials": {"air": AIR, "tnt": TNT, "steel": STEEL},
        "initial": {"material": "air", **AIR_STATE},
        "bodies": [
            {"name": "air", "material": "air", **AIR_STATE, "shape": box([0, 0, 0], [0.2, 0.2, h])},
            {"name": "plate", "material": "steel", "density": 7830, "specific_internal_energy": 0,
             "shape": box([0.06, 0, 0], [0.06 + 2 * h, 0.2, h])},
            {"name": "products", "material": "tnt", **TNT_STATE,
             "shape": {"cylinder": {"base": [0, 0, 0], "axis": [0, 0, 1], "radius": 0.03,
                                    "length": h}}},
        ],
        "boundaries": {"x_lower": "symmetry", "y_lower": "symmetry", "x_upper": "outflow",
                       "y_upper": "outflow"},
        "output": {"interval": (3.0e-5 if fast else 1.0e-4) / 4,
                   "fields": ["density", "velocity", "pressure"]},
        "solver": {"method": "mpm", "mpm": {"shape_function": "gimp", "update": "musl"}},
    }


def products_into_air(fast):
    n = 100 if fast else 400
    return {
        "name": "extreme_products_into_air",
        "time": {"end": 2.0e-5, "cfl": 0.5},
        "domain": {"lower": [0, 0, 0], "upper": [0.2, 0.002, 0.002], "cells": [n, 1, 1]},
        "materials": {"air": AIR, "tnt": TNT},
        "initial": {"material": "air", **AIR_STATE},
        "bodies": [
            {"name": "air", "material": "air", "density": 1.0e-3,
             "specific_internal_energy": 2.0685e5, "shape": box([0, 0, 0], [0.2, 0.002, 0.002])},
            {"name": "products", "material": "tnt", **TNT_STATE,
             "shape": box([0, 0, 0], [0.02, 0.002, 0.002])},
        ],
        "boundaries": {"x_lower": "wall", "x_upper": "outflow"},
        "output": {"interval": 5.0e-6, "fields": ["density", "velocity", "pressure"]},
        "solver": {"method": "mpm", "mpm": {"shape_function": "linear", "update": "musl"}},
    }


def projectile(fast, cfl):
    n = 40 if fast else 80
    h = 0.04 / n
    return {
        "name": "extreme_projectile",
        "time": {"end": 4.0e-6 if fast else 8.0e-6, "cfl": cfl},
        "domain": {"lower": [0, 0, 0], "upper": [0.04, 0.04, h], "cells": [n, n, 1]},
        "materials": {"steel": STEEL},
        "initial": {"material": "steel", "density": 7830, "specific_internal_energy": 0},
        "bodies": [
            {"name": "target", "material": "steel", "density": 7830, "specific_internal_energy": 0,
             "shape": box([0.02, 0, 0], [0.024, 0.04, h])},
            {"name": "rod", "material": "steel", "density": 7830, "specific_internal_energy": 0,
             "velocity": [6000.0, 0, 0], "shape": box([0.008, 0, 0], [0.0195, 0.004, h])},
        ],
        "boundaries": {"y_lower": "symmetry"},
        "output": {"interval": (4.0e-6 if fast else 8.0e-6) / 4,
                   "fields": ["density", "velocity", "pressure"]},
        "solver": {"method": "mpm", "mpm": {"shape_function": "cpgimp", "update": "musl"}},
    }


# name: (scene builder, pressure bound [Pa], speed bound [m/s], checked). A run
# is bounded when its largest pressure and speed and |energy audit| <= 0.1 stay
# within bounds; an unchecked case records where the edge lies (docs).
CASES = {
    "extreme_taylor_bar_2x": (taylor_bar, 1e11, 2e3, True),
    "extreme_plate_blast": (plate_blast, 1e11, 3e4, True),
    "extreme_products_into_air": (products_into_air, 1e11, 3e4, True),
    "extreme_projectile_cfl05": (lambda fast: projectile(fast, 0.5), 1e12, 2e4, True),
    "extreme_projectile_cfl1": (lambda fast: projectile(fast, 1.0), 1e12, 2e4, False),
}
ENERGY_BOUND = 0.1
# Cases that exceed a bound for a reason reported and not yet fixed: recorded, not failed.
KNOWN_DEFECTS = {
    "extreme_products_into_air": "at 400 cells thin-air particles are flung at up to 81 km/s "
                                 "(docs/stability.md (part 2))",
}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--cases", default="")
    parser.add_argument("--fast", action="store_true")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--timeout", type=float, default=900)
    args = parser.parse_args()
    wanted = set(filter(None, args.cases.split(",")))
    rows, failures = [], []
    for name, (builder, max_p, max_v, checked) in CASES.items():
        if wanted and name not in wanted:
            continue
        scene = copy.deepcopy(builder(args.fast))
        result = common.run_case(common.program_path(args.build, "mpm_solver"), scene,
                                 os.path.join(args.out, "runs", name), args.timeout, max_p, max_v)
        h = min((u - l) / c for u, l, c in zip(scene["domain"]["upper"], scene["domain"]["lower"],
                                                scene["domain"]["cells"]) if c > 1)
        steps = result["steps"] or 0
        mean_dt = float(result["time_s"] or 0) / steps if steps else 0.0
        cells_per_step = result["max_speed"] * mean_dt / h if mean_dt else ""
        energy = result["audit_energy"]
        if result["outcome"] == "bounded" and energy != "" and abs(energy) > ENERGY_BOUND:
            result["outcome"] = "unbounded"
        rows.append({"case": name, **result, "cells_per_step_at_max_speed": cells_per_step,
                     "checked": checked})
        print(f"{name}: {result['outcome']} steps {steps} max|v| {result['max_speed']:.4g} "
              f"max p {result['max_pressure']:.4g} audit mass {result['audit_mass']} energy "
              f"{result['audit_energy']} ({result['wall_s']} s) {result['message'][:160]}")
        if checked and result["outcome"] not in ("bounded", "named_error"):
            if result["outcome"] == "unbounded" and name in KNOWN_DEFECTS:
                print(f"{name}: known defect, {KNOWN_DEFECTS[name]}")
            else:
                failures.append(name)
    common.write_csv(os.path.join(args.out, "extreme_runs.csv"), rows)
    if args.check and failures:
        print("FAILED: " + ", ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
