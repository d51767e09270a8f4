#!/usr/bin/python3
"""Work-precision plot of V4 far-octant series (bench/afdmp/v4_far.sh runs).

Usage: plot_v4_far_work_precision.py OUT.png LABEL=DIR/v4_far.csv[,DIR2/v4_far.csv ...] [LABEL=...]
A series may join the v4_far.csv of several invocations (comma-separated), e.g.
a finer grid run later. For each series and each run in it (not the 1D reference): wall time against the
mean peak error over the FDM gauges (Z >= 1), against the converged 1D model
(bench/afdmp/v4_model_reference.py, the solver's own error) and against
Kingery-Bulmash. Prints the same as a table. Wall times compare runs of one
machine and load only.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FormatStrFormatter  # noqa: E402


def series(path):
    """[(label, h [m], wall [s], mean peak error vs model, vs KB)] of one v4_far.csv."""
    runs = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            if row["label"] == "1D reference" or float(row["Z"]) < 0.99:
                continue
            runs.setdefault(row["label"], []).append(row)
    out = []
    for label, rows in runs.items():
        model = [float(r["model_error"]) for r in rows]
        kb = [float(r["peak_error"]) for r in rows]
        out.append((label, float(rows[0]["h_m"]), float(rows[0]["wall_s"]),
                    sum(model) / len(model), sum(kb) / len(kb)))
    return sorted(out, key=lambda r: -r[1])


def main():
    if len(sys.argv) < 3 or any("=" not in a for a in sys.argv[2:]):
        raise SystemExit(__doc__)
    out = sys.argv[1]
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.2), sharex=True)
    print(f"{'series':<24} {'h [mm]':>7} {'wall [s]':>9} {'vs model':>9} {'vs KB':>8}")
    for arg in sys.argv[2:]:
        name, path = arg.rsplit("=", 1)
        try:
            runs = sorted((run for part in path.split(",") for run in series(part)),
                          key=lambda r: -r[1])
        except OSError as e:
            raise SystemExit(f"plot_v4_far_work_precision.py: cannot read {e.filename}: {e.strerror}")
        except KeyError as e:
            raise SystemExit(f"{path}: no column {e}; expected bench/afdmp/v4_far.py's v4_far.csv")
        if not runs:
            raise SystemExit(f"{path}: no octant runs with gauges at Z >= 1")
        for label, h, wall, model, kb in runs:
            print(f"{name:<24} {1000 * h:7.2f} {wall:9.1f} {100 * model:+8.1f}% {100 * kb:+7.1f}%")
        walls = [r[2] for r in runs]
        for ax, index in zip(axes, (3, 4)):
            errors = [abs(100 * r[index]) for r in runs]
            ax.loglog(walls, errors, "o-", label=name)
            for r, e in zip(runs, errors):
                ax.annotate(f"{1000 * r[1]:.3g}", (r[2], e), textcoords="offset points",
                            xytext=(4, 4), fontsize=7)
    for ax, what in zip(axes, ("converged 1D model", "Kingery-Bulmash")):
        ax.set_xlabel("wall time [s] (2 cores)")
        ax.set_ylabel(f"|mean peak error| vs {what}, Z ≥ 1 [%]")
        ax.grid(True, which="both", alpha=0.3)
        ax.yaxis.set_major_formatter(FormatStrFormatter("%g"))
        ax.yaxis.set_minor_formatter(FormatStrFormatter("%g"))
        ax.axhline(10, color="grey", lw=0.8, ls="--")
    axes[0].legend(fontsize=8)
    fig.suptitle("V4 far octant, 1D start: error against wall time (labels: h in mm)")
    fig.tight_layout()
    fig.savefig(out, dpi=120)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
