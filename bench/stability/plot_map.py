#!/usr/bin/python3
"""Stability map of the MPFD solvers (issue 7) from the CSV files of
run_stability.sh: the largest stable CFL per solver and case (bars, with the
first unstable CFL as a marker and the default CFL as a line), and every run of
the sweep as stable/unstable points. Writes <results>/stability_map.png.

Usage: plot_map.py <results-dir>
"""
import csv
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Each solver's default time.cfl (common/config/scene.hpp); CFDMP runs both, its MPM at 0.2.
DEFAULT_CFL = {"fdm": 0.5, "mpm_linear": 0.2, "mpm_gimp": 0.2, "cfdmp": 0.2}


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def main():
    results = Path(sys.argv[1] if len(sys.argv) > 1 else "bench/stability/results")
    limits = read(results / "cfl_limits.csv")
    runs = read(results / "cfl_runs.csv")
    labels = [f"{r['solver']}\n{r['case']}" for r in limits]
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))

    stable = [float(r["largest_stable_cfl"]) for r in limits]
    defect = [bool(r.get("reference_defect")) for r in limits]
    left.bar(range(len(limits)), stable, color=["0.7" if d else "tab:green" for d in defect],
             hatch=None, label="largest stable CFL")
    for i, d in enumerate(defect):
        if d:
            left.text(i, 0.02, "defect at\nCFL 0.1", ha="center", va="bottom", fontsize=7, rotation=90)
    for i, r in enumerate(limits):
        if r["first_unstable_cfl"]:
            left.plot(i, float(r["first_unstable_cfl"]), "rv", label="first unstable" if i == 0 else None)
    for i, r in enumerate(limits):
        left.hlines(DEFAULT_CFL[r["solver"]], i - 0.4, i + 0.4, colors="k", linestyles="--",
                    label="default CFL" if i == 0 else None)
    left.set_xticks(range(len(limits)))
    left.set_xticklabels(labels, fontsize=7, rotation=60)
    left.set_ylabel("CFL")
    left.set_title("Largest stable CFL (resolution 0.025; grey: unsound at CFL 0.1)")
    left.legend(fontsize=8)

    keys = sorted({(r["solver"], r["case"]) for r in runs}, key=labels_order(limits))
    for i, key in enumerate(keys):
        for r in runs:
            if (r["solver"], r["case"]) != key:
                continue
            ok = r["verdict"] == "stable"
            right.plot(float(r["cfl"]), i, "o" if ok else "x", color="tab:green" if ok else "tab:red")
        right.plot(DEFAULT_CFL[key[0]], i, "k|", markersize=14)
    right.set_yticks(range(len(keys)))
    right.set_yticklabels([f"{s} {c}" for s, c in keys], fontsize=8)
    right.set_xlabel("CFL")
    right.set_title("Every run: o stable, x unstable, | default")
    fig.tight_layout()
    fig.savefig(results / "stability_map.png", dpi=120)
    print(f"wrote {results / 'stability_map.png'}")


def labels_order(limits):
    order = {(r["solver"], r["case"]): i for i, r in enumerate(limits)}
    return lambda key: order.get(key, len(order))


if __name__ == "__main__":
    main()
