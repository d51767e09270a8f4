#!/usr/bin/python3
"""Long quiet runs: air at rest for END seconds in FDM, MPM (trilinear and
uGIMP, with and without shear-mode damping, and with reference_pressure) and
CFDMP across the handshake zone (1D and 2D). Measures the drift of velocity and
pressure against steps from the snapshots.

Usage: quiet_runs.py BUILD OUT [--end S] [--cases a,b,...] [--check]
Writes OUT/quiet_drift.csv (one row per case, snapshot and region),
OUT/quiet_summary.csv (one row per case: final and largest drift, outcome),
OUT/quiet_drift.png. --check exits 1 when a case marked `bound` exceeds it, a
case ends in NaN, a crash or a hang, or a coupled case's disturbance near the
coupling face exceeds NEAR_FAR_BOUND times the one far from it.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_stability_runs_common as common  # noqa: E402

RHO0 = 1.225
E0 = 2.0685e5
P0 = 0.4 * RHO0 * E0
NEAR = 0.1        # m: the "zone boundary" band on each side of the face
ROUND_OFF_PHASE = 1e-6  # m/s: below this the 2D MPM's own growth is still round-off
# m/s: a state at rest, to round-off (the bound of the cases that must stay at rest): no
# disturbance to compare near the face and far from it.
AT_REST = 1e-9
# The coupled quiet state: max|v| within NEAR of the face may exceed the far value by at most
# this factor while both grow from round-off (measured <= 1.8; a disturbance made at the
# face would show as a ratio growing with steps).
NEAR_FAR_BOUND = 10.0
# Cases that exceed a bound for a reason reported and not yet fixed: recorded, not failed.
KNOWN_DEFECTS = {
    "quiet_cfdmp_2d_gimp": "uGIMP grows from the coupling face (docs/stability.md (part 2))",
}


def face_x(nx):
    """The coupling face of the CFDMP cases: the grid line nearest x = 0.6 (MPM zone above)."""
    return round(0.6 * nx) / nx


def air_scene(name, end, cells, method, mpm=None, zones=False):
    nx, ny = cells
    upper_y = 0.01 if ny == 1 else ny / nx
    scene = {
        "name": name,
        "time": {"end": end, "cfl": 0.5},
        "domain": {"lower": [0, 0, 0], "upper": [1, upper_y, 0.01], "cells": [nx, ny, 1]},
        "materials": {"air": {"eos": {"type": "ideal_gas", "gamma": 1.4}}},
        "initial": {"material": "air", "density": RHO0, "specific_internal_energy": E0},
        "bodies": [{"name": "air", "material": "air", "density": RHO0,
                    "specific_internal_energy": E0,
                    "shape": {"box": {"lower": [0, 0, 0], "upper": [1, upper_y, 0.01]}}}],
        "boundaries": {"x_lower": "wall", "x_upper": "wall", "y_lower": "wall",
                       "y_upper": "wall", "z_lower": "symmetry", "z_upper": "symmetry"},
        "output": {"interval": end / 50, "fields": ["density", "velocity", "pressure"]},
        "solver": {"method": method},
    }
    if ny == 1:
        scene["boundaries"].update(y_lower="symmetry", y_upper="symmetry")
    if mpm is not None:
        scene["solver"]["mpm"] = mpm
    if zones:
        face = face_x(nx)
        scene["zones"] = {"fdm": {"lower": [0, 0, 0], "upper": [face + 5 / nx, upper_y, 0.01]},
                          "mpm": {"lower": [face, 0, 0], "upper": [1, upper_y, 0.01]},
                          "handshake_width": 5}
    return scene


def cases(end):
    lin = {"shape_function": "linear", "update": "musl"}
    gimp = {"shape_function": "gimp", "update": "musl"}
    damped = {"shear_damping": 0.1}
    pref = {"reference_pressure": P0}
    # (name, program, scene, bound on max |v| [m/s] that --check enforces or None)
    return [
        ("quiet_fdm_1d", "fdm_solver", air_scene("quiet_fdm_1d", end, (100, 1), "fdm"), 1e-9),
        ("quiet_fdm_2d", "fdm_solver", air_scene("quiet_fdm_2d", end, (25, 25), "fdm"), 1e-9),
        ("quiet_mpm_1d_linear", "mpm_solver",
         air_scene("quiet_mpm_1d_linear", end, (100, 1), "mpm", lin), 1e-9),
        ("quiet_mpm_2d_linear", "mpm_solver",
         air_scene("quiet_mpm_2d_linear", end, (25, 25), "mpm", lin), None),
        ("quiet_mpm_2d_linear_damped", "mpm_solver",
         air_scene("quiet_mpm_2d_linear_damped", end, (25, 25), "mpm", {**lin, **damped}), None),
        ("quiet_mpm_2d_gimp", "mpm_solver",
         air_scene("quiet_mpm_2d_gimp", end, (25, 25), "mpm", gimp), None),
        ("quiet_mpm_2d_gimp_damped", "mpm_solver",
         air_scene("quiet_mpm_2d_gimp_damped", end, (25, 25), "mpm", {**gimp, **damped}), None),
        ("quiet_mpm_2d_dyadic", "mpm_solver",
         air_scene("quiet_mpm_2d_dyadic", end, (32, 32), "mpm", lin), None),
        ("quiet_mpm_2d_linear_pref", "mpm_solver",
         air_scene("quiet_mpm_2d_linear_pref", end, (25, 25), "mpm", {**lin, **pref}), 1e-9),
        ("quiet_mpm_2d_linear_pref_damped", "mpm_solver",
         air_scene("quiet_mpm_2d_linear_pref_damped", end, (25, 25), "mpm",
                   {**lin, **pref, **damped}), 1e-9),
        ("quiet_cfdmp_1d", "coupler",
         air_scene("quiet_cfdmp_1d", end, (100, 1), "cfdmp", lin, zones=True), 1e-9),
        ("quiet_cfdmp_2d_linear", "coupler",
         air_scene("quiet_cfdmp_2d_linear", end, (40, 20), "cfdmp", lin, zones=True), None),
        ("quiet_cfdmp_2d_gimp", "coupler",
         air_scene("quiet_cfdmp_2d_gimp", end, (40, 20), "cfdmp", gimp, zones=True), None),
        ("quiet_cfdmp_2d_dyadic", "coupler",
         air_scene("quiet_cfdmp_2d_dyadic", end, (32, 16), "cfdmp", lin, zones=True), None),
        ("quiet_cfdmp_2d_linear_pref", "coupler",
         air_scene("quiet_cfdmp_2d_linear_pref", end, (40, 20), "cfdmp", {**lin, **pref},
                   zones=True), 1e-9),
        ("quiet_cfdmp_2d_gimp_pref", "coupler",
         air_scene("quiet_cfdmp_2d_gimp_pref", end, (40, 20), "cfdmp", {**gimp, **pref},
                   zones=True), 1e-9),
    ]


def drift_rows(case, run_dir, coupled):
    """max |v| and max |p - p0| / p0 per snapshot, by region."""
    rows = []
    for folder in common.snapshot_dirs(run_dir):
        solver = os.path.basename(os.path.dirname(folder)) if coupled else "all"
        for path in common.snapshot_files(folder):
            t, step, data, cells = common.read_snapshot(path)
            nx = cells[0]
            if "particles/position" in data:
                x = data["particles/position"][:, 0]
                v = np.linalg.norm(data["particles/velocity"], axis=1)
                p = data["particles/pressure"]
            else:
                x = np.broadcast_to((np.arange(nx) + 0.5) / nx, data["cells/pressure"].shape).ravel()
                v = np.linalg.norm(data["cells/velocity"].reshape(-1, 3), axis=1)
                p = data["cells/pressure"].ravel()
            regions = {"all": np.ones_like(x, dtype=bool)}
            if coupled:
                # The FDM's cells beyond its zone are not its own; the MPM's particles are all in its zone.
                face = face_x(nx)
                own = x < face + 5.0 / nx if solver == "fdm" else x >= face
                regions = {"near_face": own & (np.abs(x - face) < NEAR),
                           "far": own & (np.abs(x - face) >= NEAR)}
            for region, mask in regions.items():
                if not np.any(mask):
                    continue
                rows.append({"case": case, "solver": solver, "region": region, "step": step,
                             "time_s": t, "max_speed": float(np.max(v[mask])),
                             "max_dp_rel": float(np.max(np.abs(p[mask] - P0)) / P0)})
    return rows


def near_far_ratio(rows):
    """Largest max|v| near the coupling face over max|v| far from it, per solver and
    snapshot, while the far value is round-off growth (0 < v < ROUND_OFF_PHASE) and
    the near one is above AT_REST; None for an uncoupled run or one that stays at rest."""
    ratios = []
    for solver in ("fdm", "mpm"):
        for step in sorted({r["step"] for r in rows if r["solver"] == solver}):
            near = [r["max_speed"] for r in rows if (r["solver"], r["step"], r["region"]) ==
                    (solver, step, "near_face")]
            far = [r["max_speed"] for r in rows if (r["solver"], r["step"], r["region"]) ==
                   (solver, step, "far")]
            if near and far and 0 < far[0] < ROUND_OFF_PHASE and near[0] > AT_REST:
                ratios.append(near[0] / far[0])
    return max(ratios) if ratios else None


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(13, 9), sharex="row")
    keys = sorted({(r["case"], r["solver"], r["region"]) for r in rows})
    for key in keys:
        sel = [r for r in rows if (r["case"], r["solver"], r["region"]) == key]
        coupled = key[1] != "all"
        label = key[0].replace("quiet_", "") + (f" {key[1]} {key[2]}" if coupled else "")
        style = "--" if key[2] == "near_face" else "-"
        for col, q in enumerate(("max_speed", "max_dp_rel")):
            axes[int(coupled)][col].semilogy([r["step"] for r in sel],
                                             [max(r[q], 1e-20) for r in sel], style,
                                             marker=".", ms=3, label=label)
    for row, title in enumerate(("FDM and MPM alone", "CFDMP (dashed: within 0.1 m of the face)")):
        axes[row][0].set_ylabel("max |v| [m/s] (1e-20: exactly 0)")
        axes[row][1].set_ylabel("max |p - p0| / p0")
        axes[row][0].set_title(title)
        axes[row][1].legend(fontsize=6, loc="lower right")
        for ax in axes[row]:
            ax.set_xlabel("step")
            ax.grid(True, which="both", alpha=0.3)
    fig.suptitle("Air at rest for 100 ms: drift against steps")
    fig.tight_layout()
    fig.savefig(path, dpi=80)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("build")
    parser.add_argument("out")
    parser.add_argument("--end", type=float, default=0.1)
    parser.add_argument("--cases", default="")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--timeout", type=float, default=900)
    args = parser.parse_args()
    wanted = set(filter(None, args.cases.split(",")))
    drift, summary, failures = [], [], []
    for name, program, scene, bound in cases(args.end):
        if wanted and name not in wanted:
            continue
        out = os.path.join(args.out, "runs", name)
        result = common.run_case(common.program_path(args.build, program), scene, out,
                                 args.timeout, max_pressure=1e3 * P0, max_speed=1e4)
        rows = drift_rows(name, os.path.join(out, "run"), program == "coupler")
        drift += rows
        last = [r for r in rows if r["step"] == max(x["step"] for x in rows)] if rows else []
        row = {"case": name, **result,
               "final_max_speed": max((r["max_speed"] for r in last), default=""),
               "final_max_dp_rel": max((r["max_dp_rel"] for r in last), default=""),
               "bound_speed": bound if bound is not None else ""}
        for region in ("near_face", "far"):
            sel = [r["max_speed"] for r in last if r["region"] == region]
            row[f"final_speed_{region}"] = max(sel) if sel else ""
        ratio = near_far_ratio(rows)
        row["near_far_ratio"] = ratio if ratio is not None else ""
        summary.append(row)
        print(f"{name}: {result['outcome']} steps {result['steps']} final max|v| "
              f"{row['final_max_speed']} |dp|/p0 {row['final_max_dp_rel']} near/far "
              f"{row['near_far_ratio']} ({result['wall_s']} s)")
        ok = result["outcome"] == "bounded" and (
            bound is None or (row["final_max_speed"] != "" and
                              max(r["max_speed"] for r in rows) <= bound))
        if not ok and (bound is not None or result["outcome"] in ("nan", "crash", "hang")):
            failures.append(name)
        if ratio is not None and ratio > NEAR_FAR_BOUND:
            if name in KNOWN_DEFECTS:
                print(f"{name}: near/far ratio {ratio:.3g}: known defect, {KNOWN_DEFECTS[name]}")
            else:
                failures.append(name + " (zone boundary)")
    common.write_csv(os.path.join(args.out, "quiet_drift.csv"), drift)
    common.write_csv(os.path.join(args.out, "quiet_summary.csv"), summary)
    if drift:
        plot(drift, os.path.join(args.out, "quiet_drift.png"))
    if args.check and failures:
        print("FAILED: " + ", ".join(failures))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
