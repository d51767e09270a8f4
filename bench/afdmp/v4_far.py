#!/usr/bin/python3
"""V4 far field: peak incident overpressure and arrival of the 1D reference and
of the AFDMP octant runs (configs/afdmp_free_air_3d_far.yaml at several h)
against Kingery-Bulmash, Z = 0.5 ... 5 m/kg^(1/3).

v4_far.py OUT_DIR RUNS_CSV
RUNS_CSV rows: label, run_dir, scene, h_m, wall_s, rss_kib. A scene with
domain.geometry: spherical is read with R = the gauge's x (1D reference);
otherwise R = |position| (the charge sits at the octant's origin). The charge
is the 13.05 g sphere both hold exactly (the 1D stage seeds whole shells).
Writes OUT_DIR/v4_far.csv (one row per run and gauge: the v4_analyze.py
columns, and model_peak_Pa / model_error against the converged model of
v4_model_reference.py) and OUT_DIR/v4_far.png (peak overpressure and its error
against Z). The charge is the scene's nominal sphere also for an MPM start, whose
particles hold another mass (AFDMP samples the charge on the 3D grid).
"""
import csv
import math
import os
import sys

import yaml

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import v4_analyze  # noqa: E402
import v4_kb  # noqa: E402
import v4_model_reference  # noqa: E402


def charge_mass(scene_file):
    """Mass [kg] of the scene's one TNT sphere at rho0."""
    scene = yaml.safe_load(open(scene_file))
    radius = scene["charges"][0]["shape"]["sphere"]["radius"]
    return 4.0 / 3.0 * math.pi * radius ** 3 * scene["materials"]["tnt"]["eos"]["rho0"]


def rows_of_run(run_dir, scene_file):
    """v4_analyze's rows, with the converged model's peak and the error against it."""
    rows = v4_analyze.compare(run_dir, scene_file, charge_mass(scene_file))
    for row in rows:
        row["model_peak_Pa"] = v4_model_reference.overpressure(row["Z"])
        row["model_error"] = row["peak_Pa"] / row["model_peak_Pa"] - 1
    return rows


def main():
    out_dir, runs_csv = sys.argv[1], sys.argv[2]
    runs = list(csv.DictReader(open(runs_csv)))
    table = []
    for run in runs:
        for row in rows_of_run(run["run_dir"], run["scene"]):
            table.append({"label": run["label"], "h_m": run["h_m"], "wall_s": run["wall_s"],
                          "rss_kib": run["rss_kib"], **row})
    with open(os.path.join(out_dir, "v4_far.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0]))
        writer.writeheader()
        for row in table:
            writer.writerow({k: (f"{v:.6g}" if isinstance(v, float) else v) for k, v in row.items()})
    for run in runs:
        rows = [r for r in table if r["label"] == run["label"]]
        print(run["label"], "wall", run["wall_s"], "s, rss", run["rss_kib"], "KiB")
        for r in sorted(rows, key=lambda r: r["R_m"]):
            print(f"  {r['gauge']:5s} Z {r['Z']:5.2f} peak {r['peak_Pa'] / 1e3:8.1f} kPa "
                  f"(KB {r['kb_peak_Pa'] / 1e3:7.1f}) {100 * r['peak_error']:+6.1f} %  "
                  f"model {100 * r['model_error']:+6.1f} %  "
                  f"arrival {100 * r['arrival_error']:+6.1f} %")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 8), sharex=True)
    zs = [0.5 + 0.05 * i for i in range(91)]
    top.plot(zs, [v4_kb.overpressure(z) / 1e3 for z in zs], "k-", label="Kingery-Bulmash")
    markers = "os^vdx+*"
    for i, run in enumerate(runs):
        rows = sorted((r for r in table if r["label"] == run["label"]), key=lambda r: r["Z"])
        top.plot([r["Z"] for r in rows], [r["peak_Pa"] / 1e3 for r in rows],
                 markers[i % len(markers)], label=run["label"], mfc="none")
        bottom.plot([r["Z"] for r in rows], [100 * r["peak_error"] for r in rows],
                    markers[i % len(markers)], label=run["label"], mfc="none")
    top.set_xscale("log")
    top.set_yscale("log")
    top.set_ylabel("peak incident overpressure [kPa]")
    top.legend()
    top.set_title("V4: 13.05 g TNT sphere in free air")
    for level in (-10, 10):
        bottom.axhline(level, color="grey", ls="--", lw=0.8)
    bottom.axhline(0, color="k", lw=0.8)
    bottom.set_xlabel("Z [m/kg^(1/3)]")
    bottom.set_ylabel("peak error vs KB [%]")
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "v4_far.png"), dpi=120)


if __name__ == "__main__":
    main()
