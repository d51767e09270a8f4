#!/usr/bin/python3
"""Tables and plot of bench/afdmp/v4_work_precision.sh's runs: v4_work_precision.py OUT_DIR.

OUT_DIR/v4_work_precision.csv  per run: case, cells, h, wall time, mean and max
                               |peak error| over the Z >= 1 gauges, mean |arrival
                               error| there, mean peak error (signed) for 0.5 <= Z < 1,
                               the largest drop of p ahead of the shock at Z >= 1
OUT_DIR/v4_peak_errors.csv     per run and gauge with Z >= 0.5: peak and arrival errors
OUT_DIR/v4_work_precision.png  mean |peak error| (Z >= 1) against wall time
OUT_DIR/v4_peak_table.md       peak error [%] per gauge (rows, by Z) and run (columns)
Prints, for each pair of cases (a, b) and each run of b, the wall time a needs
for b's error (log-log interpolation between a's runs) or, outside a's range, a's
cheapest run that is at least as accurate: the factor is then a lower bound.
"""
import csv
import math
import os
import sys

import matplotlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import v4_analyze  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def mean(values):
    return sum(values) / len(values) if values else math.nan


def summarise(out):
    runs = list(csv.DictReader(open(os.path.join(out, "v4_runs.csv"))))
    latest = {}
    for run in runs:  # a rerun of a case and grid replaces the earlier one
        latest[(run["case"], int(run["cells"]))] = run
    table, per_gauge = [], []
    for (case, cells), run in sorted(latest.items()):
        mass = v4_analyze.charge_mass_of_run(os.path.join(out, f"{case}_{cells}"),
                                             os.path.join(out, f"{case}_{cells}.yaml"))
        if case == "cube_mpm" and abs(mass / v4_analyze.THESIS_CUBE_MASS - 1) > 0.01:
            print(f"{case} {cells}^3 left out: its cube holds {1e3 * mass:.2f} g, not 13.04"
                  " (h does not divide the 10 mm half side)")
            continue
        rows = list(csv.DictReader(open(os.path.join(out, f"{case}_{cells}.csv"))))
        far = [r for r in rows if float(r["Z"]) >= 1.0]
        near = [r for r in rows if 0.5 <= float(r["Z"]) < 1.0]
        for r in far + near:
            per_gauge.append({"case": case, "cells": cells, "gauge": r["gauge"],
                              "Z": r["Z"], "peak_error": r["peak_error"],
                              "arrival_error": r["arrival_error"],
                              "ahead_drop": r["ahead_drop"]})
        table.append({
            "case": case, "cells": cells, "h_mm": 1e3 * float(run["h_m"]), "tnt_g": 1e3 * mass,
            "wall_s": float(run["wall_s"]),
            "far_mean_abs_peak_error": mean([abs(float(r["peak_error"])) for r in far]),
            "far_max_abs_peak_error": max(abs(float(r["peak_error"])) for r in far),
            "far_mean_abs_arrival_error": mean([abs(float(r["arrival_error"])) for r in far]),
            "near_mean_peak_error": mean([float(r["peak_error"]) for r in near]),
            "far_min_ahead_drop": min(float(r["ahead_drop"]) for r in far),
        })
    return table, per_gauge


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v)
                             for k, v in row.items()})


def write_peak_table(path, per_gauge):
    runs = sorted({(r["case"], r["cells"]) for r in per_gauge})
    z_of = {}
    for r in per_gauge:  # Z of the first run that has the gauge (13.04 or 13.05 g)
        z_of.setdefault(r["gauge"], float(r["Z"]))
    gauges = sorted((z, g) for g, z in z_of.items())
    error = {(r["case"], r["cells"], r["gauge"]): float(r["peak_error"]) for r in per_gauge}
    with open(path, "w") as f:
        f.write("| gauge | Z | " + " | ".join(f"{c} {n}^3" for c, n in runs) + " |\n")
        f.write("|---" * (len(runs) + 2) + "|\n")
        for z, g in gauges:
            cells = [f"{100 * error[(c, n, g)]:+.1f}" if (c, n, g) in error else "" for c, n in runs]
            f.write(f"| {g} | {z:.2f} | " + " | ".join(cells) + " |\n")


def wall_at_error(points, error):
    """Wall time at `error` by log-log interpolation of (error, wall) points; None outside."""
    points = sorted(points)
    for (e0, w0), (e1, w1) in zip(points, points[1:]):
        if e0 <= error <= e1 and e0 != e1:
            s = (math.log(error) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(w0) + s * (math.log(w1) - math.log(w0)))
    return None


def main(out):
    table, per_gauge = summarise(out)
    write_csv(os.path.join(out, "v4_work_precision.csv"), table)
    write_csv(os.path.join(out, "v4_peak_errors.csv"), per_gauge)
    write_peak_table(os.path.join(out, "v4_peak_table.md"), per_gauge)
    cases = sorted({r["case"] for r in table})
    curves = {c: [(r["far_mean_abs_peak_error"], r["wall_s"]) for r in table if r["case"] == c]
              for c in cases}
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for c in cases:
        rows = sorted((r for r in table if r["case"] == c), key=lambda r: r["cells"])
        ax.loglog([r["wall_s"] for r in rows], [100 * r["far_mean_abs_peak_error"] for r in rows],
                  "o-", label=c)
        for r in rows:
            ax.annotate(f"{r['h_mm']:.3g} mm", (r["wall_s"], 100 * r["far_mean_abs_peak_error"]),
                        fontsize=7)
    ax.set_xlabel("wall time [s]")
    ax.set_ylabel("mean |P_so error| vs Kingery-Bulmash, Z >= 1 [%]")
    ax.set_title("V4 work-precision (13 g TNT; KB for the mass each run holds)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "v4_work_precision.png"), dpi=120)
    for a in cases:
        for b in cases:
            if a == b:
                continue
            for e_b, w_b in sorted(curves[b]):
                w_a = wall_at_error(curves[a], e_b)
                if w_a:
                    print(f"{a} vs {b}: at {b}'s {100 * e_b:.1f} % error, {a} needs {w_a:.1f} s"
                          f" (interpolated) and {b} {w_b:.1f} s: factor {w_b / w_a:.1f}")
                    continue
                cheaper = [(w, e) for e, w in curves[a] if e <= e_b]
                if cheaper:
                    w_a, e_a = min(cheaper)
                    print(f"{a} vs {b}: {a} reaches {100 * e_a:.1f} % in {w_a:.1f} s, better than"
                          f" {b}'s {100 * e_b:.1f} % in {w_b:.1f} s: factor >= {w_b / w_a:.1f}")
    for r in table:
        print(f"{r['case']:<11} {r['cells']:>4}^3 h {r['h_mm']:.3g} mm  TNT {r['tnt_g']:.2f} g"
              f"  wall {r['wall_s']:8.1f} s"
              f"  Z>=1 mean|peak err| {100 * r['far_mean_abs_peak_error']:5.1f} %"
              f" (max {100 * r['far_max_abs_peak_error']:5.1f} %)"
              f"  mean|arrival err| {100 * r['far_mean_abs_arrival_error']:4.1f} %"
              f"  near field (0.5<=Z<1) mean peak err {100 * r['near_mean_peak_error']:+5.1f} %"
              f"  ambient drop ahead of the shock (Z>=1) {100 * r['far_min_ahead_drop']:+5.1f} %")


if __name__ == "__main__":
    main(sys.argv[1])
