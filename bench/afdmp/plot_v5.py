#!/usr/bin/python3
"""V5 (T §3.4.4, Figs. 3.12-3.14): the phase-3 Mises histories at the plate's
centre and edge, AFDMP against pure MPM, from the CSV the V5 tests write
(tests/verification/afdmp/afdmp_steel_plate_test.cpp: $TMPDIR/mpfd-afdmp-v5-<nx>-mises.csv).
Usage: plot_v5.py CSV PNG
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(source, png):
    rows = list(csv.DictReader(open(source)))
    gauges = list(dict.fromkeys(r["gauge"] for r in rows))
    fig, axes = plt.subplots(1, len(gauges), figsize=(6 * len(gauges), 4))
    for ax, gauge in zip(axes, gauges):
        for method, label in (("afdmp", "AFDMP (phase 3)"), ("mpm", "pure MPM")):
            sel = [r for r in rows if r["gauge"] == gauge and r["method"] == method]
            ax.plot([float(r["time_s"]) * 1e6 for r in sel],
                    [float(r["mises_pa"]) / 1e6 for r in sel], label=label)
        ax.axhline(350, color="grey", lw=0.8, ls=":", label="A = 350 MPa")
        ax.set_title(gauge)
        ax.set_xlabel("t [us]")
        ax.set_ylabel("Mises stress [MPa]")
        ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
