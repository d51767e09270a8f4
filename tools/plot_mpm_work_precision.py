#!/usr/bin/python3
"""Plots the MPM work-precision benchmark (bench/mpm/mpm_work_precision).

Reads the CSV `case,shape_function,cells,steps,wall_s,error` and writes one
PNG with two log-log panels against the solver's wall time: Sod's L1(density)
per shape function, and the V2 TNT slab's largest relative deviation of the
front peak from CJ (20.99 GPa), each point labelled by its cell count N.
Uses Debian's python3-numpy and -matplotlib.

Usage: /usr/bin/python3 tools/plot_mpm_work_precision.py CSV PNG
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

COLUMNS = ("case", "shape_function", "cells", "steps", "wall_s", "error")
PANELS = (("sod", "L1 error of density [kg/m^3]", "Sod's tube to t = 0.2 (CFL 0.1)"),
          ("tnt_slab", "max |p_peak - p_CJ| / p_CJ once the front ran 20 mm",
           "V2 TNT slab, front peak vs CJ 20.99 GPa (CFL 0.1)"))


def read(path):
    data = np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8")
    missing = [c for c in COLUMNS if c not in (data.dtype.names or ())]
    if missing:
        sys.exit(f"{path}: missing columns {', '.join(missing)}")
    return np.atleast_1d(data)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    csv_path, png_path = sys.argv[1:]
    data = read(csv_path)
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    for ax, (case, ylabel, title) in zip(axes, PANELS):
        rows = data[data["case"] == case]
        for shape in np.unique(rows["shape_function"]):
            line = np.sort(rows[rows["shape_function"] == shape], order="cells")
            ax.loglog(line["wall_s"], line["error"], marker="o", label=shape)
            for row in line:
                ax.annotate(f"{int(row['cells'])}", (row["wall_s"], row["error"]),
                            textcoords="offset points", xytext=(4, 4), fontsize="x-small")
        ax.set_xlabel("solver wall time [s] (time loop only)")
        ax.set_ylabel(ylabel)
        ax.set_title(title, fontsize="medium")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.suptitle("MPM work-precision, points labelled by N")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)
    plt.close(fig)
    print(png_path)


if __name__ == "__main__":
    main()
