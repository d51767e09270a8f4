#!/usr/bin/python3
"""Plots the FDM work-precision benchmark (bench/fdm/sod_work_precision).

Reads the CSV `cfl,cells,steps,wall_s,l1_density,l1_velocity,l1_pressure` and
writes a log-log plot of L1(density) against the solver's wall time, one line
per CFL number, each point labelled by its cell count N. Uses Debian's
python3-numpy and -matplotlib.

Usage: /usr/bin/python3 tools/plot_work_precision.py CSV PNG
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLUMNS = ("cfl", "cells", "steps", "wall_s", "l1_density", "l1_velocity", "l1_pressure")


def read(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    missing = [c for c in COLUMNS if c not in (data.dtype.names or ())]
    if missing:
        sys.exit(f"{path}: missing columns {', '.join(missing)}")
    return np.atleast_1d(data)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    csv_path, png_path = sys.argv[1:]
    data = read(csv_path)
    fig, ax = plt.subplots(figsize=(7, 5))
    for cfl in np.unique(data["cfl"]):
        rows = np.sort(data[data["cfl"] == cfl], order="cells")
        ax.loglog(rows["wall_s"], rows["l1_density"], marker="o", label=f"CFL {cfl:g}")
        for row in rows:
            ax.annotate(f"{int(row['cells'])}", (row["wall_s"], row["l1_density"]),
                        textcoords="offset points", xytext=(4, 4), fontsize="x-small")
    ax.set_xlabel("solver wall time [s] (best of repeats, time loop only)")
    ax.set_ylabel("L1 error of density [kg/m^3]")
    ax.set_title("FDM work-precision: Sod's tube to t = 0.2, points labelled by N")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    plt.close(fig)
    print(png_path)


if __name__ == "__main__":
    main()
