#!/usr/bin/python3
"""Where V6's products' tail is lost in the MPM zone (docs/coupler.md, "Where the tail is lost").

  v6_tail.py run  --build BUILD --out DIR [--h MM] [--end S]   two CFDMP runs, TNT: the MPM with
                                                               linear and with uGIMP shapes
  v6_tail.py plot --out DIR --ref FDM_RUN [--png FILE]         the figure (FDM_RUN: a fine pure-FDM
                                                               run's directory with gauges.csv)

Scenes: bench/coupler/v6_bench.py's re-gridded configs/cfdmp_blast_2d.yaml with snapshots every
2.5 us. The figure: gauge p2 against the reference, the density along y = 250 mm at 40 us in the MPM
zone against the run's own FDM zone mirrored (x -> -x; by symmetry the same flow), and the linear
run's transverse velocity error v_y(MPM, mass-weighted per cell) - v_y(mirrored FDM cell).
"""
import argparse
import os
import re
import subprocess
import sys

import h5py
import matplotlib
import numpy as np

import v6_bench

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

SHAPES = ("linear", "gimp")
SNAPSHOT = 16  # 40 us at 2.5 us a snapshot


def run(args):
    for shape in SHAPES:
        text = v6_bench.scene_text("cfdmp", args.h * 1e-3, args.end).replace(
            "interval: 2.0e-5", "interval: 2.5e-6")
        text, count = re.subn(r"shape_function: \w+", f"shape_function: {shape}", text)
        if count != 1:
            sys.exit(f"v6_tail: configs/cfdmp_blast_2d.yaml names shape_function {count} times, "
                     "expected once")
        scene = os.path.join(args.out, f"v6_tail_{shape}.yaml")
        os.makedirs(args.out, exist_ok=True)
        open(scene, "w").write(text)
        env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
        subprocess.run([os.path.join(args.build, "coupler", "coupler"), "run", scene, "--out",
                        os.path.join(args.out, shape), "--overwrite"], env=env, check=True,
                       stdout=subprocess.DEVNULL)


def gauges(run_dir):
    d = np.genfromtxt(os.path.join(run_dir, "gauges.csv"), delimiter=",", names=True)
    n = d.dtype.names
    return d[n[0]] * 1e6, d[n[2]] / 1e6, d[n[7]] / 1e6


def snapshots(run_dir):
    name = f"snapshot_{SNAPSHOT:06d}.h5"
    return (h5py.File(os.path.join(run_dir, "fdm", "snapshots", name), "r"),
            h5py.File(os.path.join(run_dir, "mpm", "snapshots", name), "r"))


def density_line(run_dir):
    fdm, mpm = snapshots(run_dir)
    o, h = fdm["grid"].attrs["origin"], fdm["grid"].attrs["spacing"][0]
    x = o[0] + (np.arange(fdm["cells/density"].shape[2]) + 0.5) * h
    j = int(round((0.25 - o[1]) / h))
    rho = fdm["cells/density"][0, j - 1:j + 1, :].mean(0)
    p = mpm["particles/position"][:]
    m, r = mpm["particles/mass"][:], mpm["particles/density"][:]
    on_line = np.abs(p[:, 1] - 0.25) < h
    xs = np.arange(0.11 + h / 2, 0.16, h)
    line = []
    for xc in xs:
        c = on_line & (np.abs(p[:, 0] - xc) < h / 2)
        line.append(m[c].sum() / (m[c] / r[c]).sum() if c.any() else np.nan)
    return -x[x < 0] * 1e3, rho[x < 0], xs * 1e3, np.array(line)


def transverse_error(run_dir, box=(110, 150, 230, 270)):
    fdm, mpm = snapshots(run_dir)
    o, h = fdm["grid"].attrs["origin"], fdm["grid"].attrs["spacing"][0]
    p, v, m = mpm["particles/position"][:], mpm["particles/velocity"][:], mpm["particles/mass"][:]
    x0, x1, y0, y1 = (b * 1e-3 for b in box)
    nx, ny = int(round((x1 - x0) / h)), int(round((y1 - y0) / h))
    s = (p[:, 0] >= x0) & (p[:, 0] < x1) & (p[:, 1] >= y0) & (p[:, 1] < y1)
    ix = np.minimum(((p[s, 0] - x0) / h).astype(int), nx - 1)
    iy = np.minimum(((p[s, 1] - y0) / h).astype(int), ny - 1)
    mass, momentum = np.zeros((ny, nx)), np.zeros((ny, nx))
    np.add.at(mass, (iy, ix), m[s])
    np.add.at(momentum, (iy, ix), m[s] * v[s, 1])
    rows = ((y0 + (np.arange(ny) + 0.5) * h - o[1]) / h).astype(int)
    cols = ((-(x0 + (np.arange(nx) + 0.5) * h) - o[0]) / h).astype(int)
    mirrored = fdm["cells/velocity"][0, :, :, 1][np.ix_(rows, cols)]
    return momentum / np.where(mass > 0, mass, np.nan) - mirrored, box


def plot(args):
    fig, ax = plt.subplots(1, 3, figsize=(13, 3.8))
    t, _, p2 = gauges(args.ref)
    ax[0].plot(t, p2, "k-", lw=2, label="pure FDM (reference)")
    t, p1, p2 = gauges(os.path.join(args.out, "linear"))
    ax[0].plot(t, p1, "C0:", label="CFDMP p1 (FDM zone)")
    ax[0].plot(t, p2, "C3-", label="CFDMP p2, MPM linear")
    t, _, p2 = gauges(os.path.join(args.out, "gimp"))
    ax[0].plot(t, p2, "C2--", label="CFDMP p2, MPM uGIMP")
    ax[0].set(xlim=(10, 45), xlabel="t [µs]", ylabel="p [MPa]")
    ax[0].set_title("V6 gauge p2 (125 mm), TNT", fontsize=9)
    ax[0].legend(fontsize=7)
    xm, mirror, xs, linear = density_line(os.path.join(args.out, "linear"))
    _, _, _, gimp = density_line(os.path.join(args.out, "gimp"))
    ax[1].plot(xm, mirror, "k-", lw=2, label="FDM zone, mirrored (x → −x)")
    ax[1].plot(xs, linear, "C3.-", label="MPM zone, linear")
    ax[1].plot(xs, gimp, "C2.--", label="MPM zone, uGIMP")
    ax[1].axvline(110, color="gray", lw=0.8)
    ax[1].axvline(125.1, color="gray", ls=":", lw=0.8)
    ax[1].set(xlim=(100, 160), ylim=(30, 170), xlabel="|x| [mm] along y = 250 mm",
              ylabel="ρ [kg/m³]")
    ax[1].set_title("t = 40 µs: products density (face 110, gauge 125)", fontsize=9)
    ax[1].legend(fontsize=7)
    error, box = transverse_error(os.path.join(args.out, "linear"))
    image = ax[2].imshow(error, origin="lower", extent=box, cmap="RdBu_r", vmin=-150, vmax=150)
    plt.colorbar(image, ax=ax[2], label="v_y(MPM) − v_y(FDM mirrored) [m/s]")
    ax[2].set(xlabel="x [mm]", ylabel="y [mm]")
    ax[2].set_title("t = 40 µs, MPM linear: transverse velocity error", fontsize=9)
    plt.tight_layout()
    plt.savefig(args.png or os.path.join(args.out, "v6_tail.png"), dpi=80)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=("run", "plot"))
    parser.add_argument("--out", required=True)
    parser.add_argument("--build", default="build")
    parser.add_argument("--h", type=float, default=1.0, help="cell size [mm]")
    parser.add_argument("--end", type=float, default=4.5e-5, help="end time [s]")
    parser.add_argument("--ref", help="pure-FDM reference run directory (plot)")
    parser.add_argument("--png", help="figure file (plot; default OUT/v6_tail.png)")
    args = parser.parse_args()
    if args.mode == "run":
        run(args)
    else:
        plot(args)


if __name__ == "__main__":
    main()
