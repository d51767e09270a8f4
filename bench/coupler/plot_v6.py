#!/usr/bin/python3
"""Plots of bench/coupler/v6_bench.py's results: plot_v6.py OUT_DIR.

OUT_DIR/v6_gauges.png         pressure at the two tracking points, every run
OUT_DIR/v6_work_precision.png gauge peak-overpressure error against the pure-FDM
                              reference (the finest fdm run) against wall time
OUT_DIR/v6_overhead.png       coupling overhead share per transport
Also writes OUT_DIR/v6_work_precision.csv (the errors plotted).
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

GAUGES = ("p1_fdm", "p2_mpm")


def history(run_dir, gauge):
    rows = list(csv.reader(open(os.path.join(run_dir, "gauges.csv"))))
    j = next(i for i, c in enumerate(rows[0]) if c.startswith(gauge + ".pressure"))
    data = [[float(x) for x in r] for r in rows[1:]]
    return [r[0] * 1e6 for r in data], [(r[j] - data[0][j]) / 1e6 for r in data]


def main(out):
    rows = [r for r in csv.DictReader(open(os.path.join(out, "v6_runs.csv")))
            if r["status"] == "completed"]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5), sharey=True)
    for ax, gauge in zip(axes, GAUGES):
        for r in rows:
            if r["method"] == "cfdmp" and r["transport"] != "inproc":
                continue
            t, p = history(os.path.join(out, "runs", r["tag"]), gauge)
            ax.plot(t, p, label=f"{r['method']} h = {float(r['h_mm']):g} mm", lw=1)
        ax.set_title(f"{gauge} ({'-' if gauge == 'p1_fdm' else ''}125, 250) mm")
        ax.set_xlabel("t [us]")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("overpressure [MPa]")
    axes[1].legend(fontsize=8)
    fig.suptitle("V6 (T §4.4.2): gauge histories")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "v6_gauges.png"), dpi=120)

    refs = sorted((r for r in rows if r["method"] == "fdm"), key=lambda r: float(r["h_mm"]))
    if refs:
        ref = refs[0]
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        errors = []
        for gauge, marker in zip(GAUGES, ("o", "s")):
            for method in ("cfdmp", "mpm"):
                pts = sorted(((float(r["wall_s"]), abs(float(r[gauge + "_peak_Pa"]) /
                                                        float(ref[gauge + "_peak_Pa"]) - 1),
                               float(r["h_mm"])) for r in rows
                              if r["method"] == method and r["transport"] == "inproc"))
                if not pts:
                    continue
                errors += [{"method": method, "gauge": gauge, "h_mm": h, "wall_s": w,
                            "peak_error": e} for w, e, h in pts]
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], marker=marker,
                          ls="-" if method == "cfdmp" else ":", label=f"{method} {gauge}")
                for w, e, h in pts:
                    ax.annotate(f"{h:g} mm", (w, e), fontsize=7)
        ax.set_xlabel("wall time [s]")
        ax.set_ylabel(f"|peak / peak_ref - 1| (ref: fdm h = {float(ref['h_mm']):g} mm)")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "v6_work_precision.png"), dpi=120)
        with open(os.path.join(out, "v6_work_precision.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=["method", "gauge", "h_mm", "wall_s", "peak_error"])
            w.writeheader()
            w.writerows(errors)

    shares = [r for r in rows if r.get("coupling_overhead_share")]
    if shares:
        fig, ax = plt.subplots(figsize=(6.5, 4))
        labels = [f"{r['transport']}\nh = {float(r['h_mm']):g} mm" for r in shares]
        ax.bar(labels, [float(r["coupling_overhead_share"]) for r in shares])
        ax.set_ylabel("1 - slower Advance / step time")
        ax.set_title("V6 coupling overhead share")
        fig.tight_layout()
        fig.savefig(os.path.join(out, "v6_overhead.png"), dpi=120)


if __name__ == "__main__":
    main(sys.argv[1])
