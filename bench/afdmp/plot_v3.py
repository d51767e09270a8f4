#!/usr/bin/python3
"""Plots of bench/afdmp/v3_bench.py's results: plot_v3.py OUT_DIR.

OUT_DIR/v3_cost.png       wall time and peak RSS, AFDMP against pure MPM, per h
OUT_DIR/v3_interface.png  air inside and products outside the interface band and
                          the anisotropy against time, per h and source
OUT_DIR/v3_particles.png  at the finest h run by both, 10/50/90 us: the products' volume
                          fraction of AFDMP's FDM cells and of pure MPM's binned
                          cells (white: no particle), and pure MPM's particles by material (T Figs. 3.8,
                          3.9; AFDMP's FDM snapshots hold no tracers)
"""
import csv
import glob
import os
import sys

import h5py
import matplotlib
import numpy

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

TIMES = (1e-5, 5e-5, 9e-5)


def snapshot_at(folder, time):
    best = min(glob.glob(os.path.join(folder, "*.h5")),
               key=lambda f: abs(h5py.File(f, "r").attrs["time"] - time))
    return h5py.File(best, "r")


def main(out):
    runs = list(csv.DictReader(open(os.path.join(out, "v3_runs.csv"))))
    hs = sorted({float(r["h_mm"]) for r in runs}, reverse=True)
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for k, method in enumerate(("afdmp", "mpm")):
        rows = {float(r["h_mm"]): r for r in runs if r["method"] == method}
        xs = [i + (k - 0.5) * 0.35 for i in range(len(hs))]
        axes[0].bar(xs, [float(rows[h]["wall_s"]) if h in rows else 0 for h in hs], 0.35,
                    label="AFDMP" if method == "afdmp" else "pure MPM")
        axes[1].bar(xs, [float(rows[h]["peak_rss_mib"]) if h in rows else 0 for h in hs], 0.35,
                    label="AFDMP" if method == "afdmp" else "pure MPM")
    for ax, label in zip(axes, ("wall time [s]", "peak RSS [MiB]")):
        ax.set_yscale("log")
        ax.set_xticks(range(len(hs)), [f"h = {h:g} mm" for h in hs])
        ax.set_ylabel(label)
        ax.legend()
    fig.suptitle("V3, 90 us: AFDMP against pure MPM")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "v3_cost.png"), dpi=120)

    rows = list(csv.DictReader(open(os.path.join(out, "v3_interface.csv"))))
    fig, axes = plt.subplots(1, 3, figsize=(14, 4))
    for h in hs:
        for source in ("afdmp_cells", "mpm_cells", "mpm_particles"):
            sel = [r for r in rows if float(r["h_mm"]) == h and r["source"] == source]
            if not sel:
                continue
            t = [float(r["time_s"]) * 1e6 for r in sel]
            style = {"afdmp_cells": "o-", "mpm_cells": "s--", "mpm_particles": "^:"}[source]
            for ax, key in zip(axes, ("air_inside", "products_outside", "anisotropy")):
                ax.plot(t, [max(float(r[key]), 1e-7) for r in sel], style,
                        label=f"{source}, h = {h:g} mm")
    for ax, title in zip(axes, ("air inside r_i - 3h (0 drawn at 1e-7)",
                                "products beyond r_i + 3h (0 drawn at 1e-7)",
                                "anisotropy (max - min) / mean r_i")):
        ax.set_yscale("log")
        ax.set_xlabel("t [us]")
        ax.set_title(title)
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "v3_interface.png"), dpi=120)

    both = [h for h in hs if {r["method"] for r in runs if float(r["h_mm"]) == h} == {"afdmp", "mpm"}]
    h = both[-1]
    fig, axes = plt.subplots(3, 3, figsize=(13, 12.5))
    mpm_folder = os.path.join(out, f"v3_mpm_h{h:g}mm", "snapshots")
    sources = ((os.path.join(out, f"v3_afdmp_h{h:g}mm", "fdm", "snapshots"), "AFDMP cells"),
               (mpm_folder, "pure MPM cells"), (mpm_folder, "pure MPM particles"))
    cmap = matplotlib.colormaps["coolwarm"].with_extremes(bad="white")
    for col, time in enumerate(TIMES):
        f = snapshot_at(mpm_folder, time)
        pos = f["particles/position"][:]
        mat = f["particles/material"][:]
        radius = (pos[:, 0] ** 2 + pos[:, 1] ** 2) ** 0.5
        reach = 1.5 * radius[mat == 1].max() * 1e3
        for row, (folder, title) in enumerate(sources):
            ax = axes[row, col]
            f = snapshot_at(folder, time)
            if row < 2:
                theta = f["cells/volume_fraction_tnt"][0]
                empty = theta + f["cells/volume_fraction_air"][0] <= 0  # MPM: no particle
                theta = numpy.ma.masked_where(empty, theta)
                image = ax.imshow(theta, origin="lower", extent=(0, 500, 0, 500), vmin=0, vmax=1,
                                  cmap=cmap, interpolation="nearest")
            else:
                keep = radius * 1e3 < 1.5 * reach
                for m, colour, label in ((0, "tab:blue", "air"), (1, "tab:red", "products")):
                    sel = keep & (mat == m)
                    ax.scatter(pos[sel, 0] * 1e3, pos[sel, 1] * 1e3, s=0.5, c=colour, label=label)
            ax.set_aspect("equal")
            ax.set_xlim(0, reach)
            ax.set_ylim(0, reach)
            ax.set_title(f"{title}, t = {f.attrs['time'] * 1e6:.0f} us")
            ax.set_xlabel("x [mm]")
            ax.set_ylabel("y [mm]")
    fig.colorbar(image, ax=axes[:2, :].ravel().tolist(), shrink=0.6, label="products volume fraction")
    axes[2, 0].legend(markerscale=10)
    fig.suptitle(f"V3 products/air at h = {h:g} mm (T Figs. 3.8, 3.9)")
    fig.savefig(os.path.join(out, "v3_particles.png"), dpi=100)

if __name__ == "__main__":
    main(sys.argv[1])
