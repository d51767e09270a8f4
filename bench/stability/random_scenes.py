#!/usr/bin/python3
"""Randomised scenes: for each seed of a fixed list, a valid scene within
physical ranges (method fdm, mpm or cfdmp; 1D or 2D; grid size; domain size;
a charge of TNT products or hot air: size, position, pressure; an optional
steel plate (MPM) or water block (FDM); boundary types; CFL; MPM shape
function; FDM viscosity switch power 1 or 2), with its end time set for about STEPS steps. Each is run through
`fdm_solver run`, `mpm_solver run` or `coupler run` under a timeout and must
either run bounded or fail with a named error: never NaN, crash or hang.

Usage: random_scenes.py BUILD OUT [--seeds 0-59 | --seeds 1,5,9] [--steps 300] [--check]
Writes OUT/random_scenes.csv (one row per seed: its parameters and outcome).
"""
import argparse
import math
import os
import random
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_stability_runs_common as common  # noqa: E402

AIR = {"eos": {"type": "ideal_gas", "gamma": 1.4}}
TNT = {"eos": {"type": "jwl", "rho0": 1630, "A": 3.712e11, "B": 3.21e9, "R1": 4.15,
               "R2": 0.95, "omega": 0.3, "E0": 6.993e9}}
STEEL = {"eos": {"type": "mie_gruneisen", "rho0": 7830, "C0": 4569, "S": 1.49, "gamma0": 2.17},
         "strength": {"type": "johnson_cook", "A": 7.92e8, "B": 5.10e8, "n": 0.26, "C": 0.014,
                      "m": 1.03, "T_melt": 1793, "specific_heat": 477,
                      "shear_modulus": 7.75e10}}
WATER = {"eos": {"type": "polynomial", "rho0": 1000, "A1": 2.2e9, "A2": 9.54e9, "A3": 1.457e10,
                 "B0": 0.28, "B1": 0.28, "T1": 2.2e9}}
RHO_AIR, E_AIR = 1.225, 2.0685e5
P_AIR = 0.4 * RHO_AIR * E_AIR
C_TNT = 7.0e3   # m/s: sound speed bound of the products at their constant-volume state


def box(lower, upper):
    return {"box": {"lower": lower, "upper": upper}}


def generate(seed, steps):
    """One scene from the seed, with the parameters that describe it."""
    rng = random.Random(seed)
    method = rng.choice(["fdm", "mpm", "cfdmp"])
    dim = rng.choice([1, 2])
    length = rng.uniform(0.2, 2.0)
    nx = rng.randint(30, 200) if dim == 1 else rng.randint(16, 60)
    h = length / nx
    ny = 1 if dim == 1 else rng.randint(8, 40)
    upper = [length, ny * h, h]
    cfl = round(rng.uniform(0.1, 1.0), 3)
    charge_kind = rng.choice(["tnt", "hot_air"])
    radius = rng.uniform(0.02, 0.15) * length
    centre = [rng.uniform(0.0, 0.5) * length, rng.uniform(0.0, 1.0) * upper[1], 0.0]
    faces = ["outflow", "wall", "symmetry"] + (["non_reflecting"] if method == "mpm" else [])
    boundaries = {f"{a}_{s}": rng.choice(faces) for a in "xy" for s in ("lower", "upper")}
    boundaries.update(z_lower="symmetry", z_upper="symmetry")
    if dim == 1:
        boundaries.update(y_lower="symmetry", y_upper="symmetry")
    materials = {"air": AIR}
    bodies = [{"name": "air", "material": "air", "density": RHO_AIR,
               "specific_internal_energy": E_AIR, "shape": box([0, 0, 0], upper)}]
    extra = rng.choice(["none", "solid"])
    if extra == "solid" and method in ("mpm", "cfdmp"):
        materials["steel"] = STEEL
        x0 = rng.uniform(0.6, 0.85) * length
        # At ambient pressure: at e = 0 (p = 0) the FDM, which holds every body on the
        # whole grid in cfdmp, stops at step 0 (docs/stability.md (part 2)).
        bodies.append({"name": "plate", "material": "steel", "density": 7830, "pressure": P_AIR,
                       "shape": box([x0, 0, 0], [x0 + max(2 * h, 0.02 * length), upper[1], h])})
    elif extra == "solid" and method == "fdm":
        materials["water"] = WATER
        x0 = rng.uniform(0.6, 0.85) * length
        bodies.append({"name": "water", "material": "water", "density": 1000, "pressure": P_AIR,
                       "shape": box([x0, 0, 0], [x0 + 0.1 * length, upper[1], h])})
    if charge_kind == "tnt":
        materials["tnt"] = TNT
        charge = {"name": "charge", "material": "tnt", "density": 1630,
                  "specific_internal_energy": 4.2902e6}
        c_max, p_charge = C_TNT, 8.38e9
    else:
        ratio = 10 ** rng.uniform(1, 4)
        rho = RHO_AIR * rng.uniform(1, 10)
        p_charge = P_AIR * ratio
        charge = {"name": "charge", "material": "air", "density": rho, "pressure": p_charge}
        c_max = math.sqrt(1.4 * p_charge / rho) * 2.5   # + the flow speed it drives
    if dim == 2:
        shape = {"cylinder": {"base": centre, "axis": [0, 0, 1], "radius": radius, "length": h}}
    else:
        shape = box([max(0.0, centre[0] - radius), 0, 0], [centre[0] + radius, upper[1], h])
    bodies.append({**charge, "shape": shape})
    end = steps * cfl * h / c_max
    scene = {
        "name": f"random_{seed}",
        "time": {"end": end, "cfl": cfl, "max_steps": 20 * steps},
        "domain": {"lower": [0, 0, 0], "upper": upper, "cells": [nx, ny, 1]},
        "materials": materials,
        "initial": {"material": "air", "density": RHO_AIR, "specific_internal_energy": E_AIR},
        "bodies": bodies,
        "boundaries": boundaries,
        "output": {"interval": end / 2, "fields": ["density", "velocity", "pressure"]},
        "solver": {"method": method},
    }
    shape_function = rng.choice(["linear", "gimp", "cpgimp"])
    if method in ("mpm", "cfdmp"):
        # The update scheme is left to its default (usavg, the scheme users get).
        scene["solver"]["mpm"] = {"shape_function": shape_function}
    if method == "cfdmp":
        w = 5
        # The FDM zone ends w cells past the face and its 3 ghost layers must fit in the grid;
        # a plate lies beyond them and the next cell, whose particles reach the ghost cells'
        # nodes (the scene check's rule: structures live in the MPM zone).
        face = min(round(rng.uniform(0.6, 0.85) * nx), nx - w - 3)
        if extra == "solid":
            # At least 2 cells below the face (the strip and deposit layers); the plate
            # then moves right where it must, on the smallest grids and by the cell
            # the check added to the ghost layers (the face stays where it was drawn).
            face = max(2, min(face, math.floor(x0 / h + 1e-9) - w - 3))
            plate = bodies[1]["shape"]["box"]
            shift = max(0.0, (face + w + 4) * h - plate["lower"][0])
            plate["lower"][0] += shift
            plate["upper"][0] += shift
        scene["zones"] = {"fdm": {"lower": [0, 0, 0], "upper": [(face + w) * h, upper[1], h]},
                          "mpm": {"lower": [face * h, 0, 0], "upper": upper},
                          "handshake_width": w}
    # Drawn last, so that every other draw of a seed is what it was before this one.
    switch_power = rng.choice([1, 2])
    if method in ("fdm", "cfdmp"):
        scene["solver"]["fdm"] = {"viscosity_switch_power": switch_power}
    params = {"seed": seed, "method": method, "dim": dim, "cells": f"{nx}x{ny}",
              "length_m": round(length, 4), "cfl": cfl, "charge": charge_kind,
              "charge_pressure_pa": f"{p_charge:.3g}", "charge_radius_m": round(radius, 4),
              "extra": extra, "shape_function": shape_function if method != "fdm" else "",
              "switch_power": switch_power if method != "mpm" else "",
              "boundaries": " ".join(boundaries[f"{a}_{s}"] for a in "xy"
                                     for s in ("lower", "upper"))}
    return scene, params, p_charge


def program_of(method):
    return {"fdm": "fdm_solver", "mpm": "mpm_solver", "cfdmp": "coupler"}[method]


def parse_seeds(text):
    seeds = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            seeds += list(range(int(a), int(b) + 1))
        elif part:
            seeds.append(int(part))
    return seeds


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--seeds", default="0-59")
    parser.add_argument("--steps", type=int, default=300)
    parser.add_argument("--timeout", type=float, default=180)
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    rows = []
    for seed in parse_seeds(args.seeds):
        scene, params, p_charge = generate(seed, args.steps)
        program = common.program_path(args.build, program_of(params["method"]))
        result = common.run_case(program, scene, os.path.join(args.out, "runs", f"random_{seed}"),
                                 args.timeout, max_pressure=100 * p_charge, max_speed=5e4)
        rows.append({**params, **result})
        print(f"seed {seed} {params['method']} {params['dim']}D {params['cells']} cfl "
              f"{params['cfl']} {params['charge']}: {result['outcome']} steps {result['steps']} "
              f"({result['wall_s']} s) {result['message'][:200] if result['outcome'] != 'bounded' else ''}")
    common.write_csv(os.path.join(args.out, "random_scenes.csv"), rows)
    counts = {o: sum(r["outcome"] == o for r in rows) for o in common.OUTCOMES}
    print("outcomes: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    bad = [r["seed"] for r in rows if r["outcome"] in ("unbounded", "nan", "crash", "hang")]
    if args.check and bad:
        print("FAILED seeds: " + ", ".join(map(str, bad)))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
