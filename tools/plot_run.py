#!/usr/bin/python3
"""Plots an MPFD output folder (docs/output.md, format version 1).

Writes DIR/plots/profiles.png (every scalar cell field along x through the
grid's centre line, one curve per snapshot), for 2D and 3D grids also
DIR/plots/pressure_maps.png (pressure in the mid-z plane at every snapshot,
with the material interface), and DIR/plots/gauges.png (every gauge quantity
against time). Uses Debian's python3-numpy, -h5py, -matplotlib.

Usage: /usr/bin/python3 tools/plot_run.py DIR
"""
import glob
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.colors  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

SUPPORTED_VERSION = 1


def units(dataset):
    value = dataset.attrs.get("units", b"")
    text = value.decode() if isinstance(value, bytes) else str(value)
    return f"[{text}]" if text else ""


def use_log_scale_if_wide(ax, values):
    positive = values[values > 0]
    if positive.size == values.size and positive.size and positive.max() > 100 * positive.min():
        ax.set_yscale("log")


def check_version(h5, path):
    version = int(h5.attrs["format_version"])
    if version != SUPPORTED_VERSION:
        sys.exit(f"{path}: format_version {version}, this script reads {SUPPORTED_VERSION}")


def plot_profiles(out_dir, plots_dir):
    files = sorted(glob.glob(os.path.join(out_dir, "snapshots", "snapshot_*.h5")))
    if not files:
        return None
    with h5py.File(files[0], "r") as h5:
        check_version(h5, files[0])
        fields = [n for n, d in h5["cells"].items() if d.ndim == 3]
        origin, spacing = h5["grid"].attrs["origin"], h5["grid"].attrs["spacing"]
        nz, ny, nx = h5["cells"][fields[0]].shape
    x = origin[0] + (np.arange(nx) + 0.5) * spacing[0]
    fig, axes = plt.subplots(len(fields), 1, figsize=(7, 2.2 * len(fields)), sharex=True,
                             squeeze=False)
    for path in files:
        with h5py.File(path, "r") as h5:
            label = f"t = {h5.attrs['time'] * 1e6:.1f} µs"
            for ax, name in zip(axes[:, 0], fields):
                data = h5["cells"][name]
                line = data[nz // 2, ny // 2, :]
                ax.plot(x * 1e3, line, label=label)
                ax.set_ylabel(f"{name}\n{units(data)}")
                use_log_scale_if_wide(ax, line)
    axes[-1, 0].set_xlabel("x [mm]")
    axes[0, 0].legend(fontsize="small")
    fig.suptitle("cell fields along x through the grid centre")
    fig.tight_layout()
    target = os.path.join(plots_dir, "profiles.png")
    fig.savefig(target, dpi=110)
    plt.close(fig)
    return target


def plot_pressure_maps(out_dir, plots_dir):
    files = sorted(glob.glob(os.path.join(out_dir, "snapshots", "snapshot_*.h5")))
    if not files:
        return None
    with h5py.File(files[0], "r") as h5:
        if "pressure" not in h5["cells"] or h5["cells"]["pressure"].shape[1] < 2:
            return None
        origin, spacing = h5["grid"].attrs["origin"], h5["grid"].attrs["spacing"]
        nz, ny, nx = h5["cells"]["pressure"].shape
    extent = [origin[0] * 1e3, (origin[0] + nx * spacing[0]) * 1e3,
              origin[1] * 1e3, (origin[1] + ny * spacing[1]) * 1e3]
    columns = min(3, len(files))
    rows = (len(files) + columns - 1) // columns
    fig, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 3.6 * rows), squeeze=False)
    for ax in axes.flat[len(files):]:
        ax.axis("off")
    for ax, path in zip(axes.flat, files):
        with h5py.File(path, "r") as h5:
            p = h5["cells"]["pressure"][nz // 2, :, :]
            image = ax.imshow(p, origin="lower", extent=extent, cmap="inferno",
                              norm=matplotlib.colors.LogNorm(vmin=max(p.min(), 1e3), vmax=p.max()))
            fig.colorbar(image, ax=ax, label="pressure [Pa]")
            if "material" in h5["cells"]:
                m = h5["cells"]["material"][nz // 2, :, :]
                if np.unique(m).size > 1:
                    x = origin[0] * 1e3 + (np.arange(nx) + 0.5) * spacing[0] * 1e3
                    y = origin[1] * 1e3 + (np.arange(ny) + 0.5) * spacing[1] * 1e3
                    ax.contour(x, y, (m == m.flat[0]).astype(float), levels=[0.5], colors="cyan",
                               linewidths=0.8)
            ax.set_title(f"t = {h5.attrs['time'] * 1e6:.0f} µs")
            ax.set_xlabel("x [mm]")
            ax.set_ylabel("y [mm]")
    fig.suptitle("pressure in the mid-plane (cyan: material interface)")
    fig.tight_layout()
    target = os.path.join(plots_dir, "pressure_maps.png")
    fig.savefig(target, dpi=100)
    plt.close(fig)
    return target


def plot_gauges(out_dir, plots_dir):
    path = os.path.join(out_dir, "gauges.h5")
    if not os.path.exists(path):
        return None
    with h5py.File(path, "r") as h5:
        check_version(h5, path)
        time = h5["time"][:]
        gauges = list(h5["gauges"].keys())
        if not gauges or time.size == 0:
            return None
        quantities = list(h5["gauges"][gauges[0]].keys())
        fig, axes = plt.subplots(len(quantities), 1, figsize=(7, 2.4 * len(quantities)),
                                 sharex=True, squeeze=False)
        for ax, q in zip(axes[:, 0], quantities):
            for g in gauges:
                data = h5["gauges"][g][q]
                ax.plot(time * 1e6, data[:], marker="." if time.size < 30 else None, label=g)
                ax.set_ylabel(f"{q}\n{units(data)}")
        axes[-1, 0].set_xlabel("time [µs]")
        axes[0, 0].legend(fontsize="small")
    fig.suptitle("gauge histories")
    fig.tight_layout()
    target = os.path.join(plots_dir, "gauges.png")
    fig.savefig(target, dpi=110)
    plt.close(fig)
    return target


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    out_dir = sys.argv[1]
    if not os.path.isdir(out_dir):
        sys.exit(f"plot_run.py: {out_dir} is not an output folder")
    plots_dir = os.path.join(out_dir, "plots")
    os.makedirs(plots_dir, exist_ok=True)
    for target in (plot_profiles(out_dir, plots_dir), plot_pressure_maps(out_dir, plots_dir),
                   plot_gauges(out_dir, plots_dir)):
        if target:
            print(target)


if __name__ == "__main__":
    main()
