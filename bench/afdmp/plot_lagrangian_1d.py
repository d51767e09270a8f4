#!/usr/bin/python3
"""Table and figure of the converged V4 model reference (lagrangian_1d.py runs).

plot_lagrangian_1d.py [--png FILE] [--variants DIR ...] RUN_DIR ...

RUN_DIRs: runs of one start at several --dr (any order; sorted by dr). Prints a
markdown table: per Z, the gauge peak overpressure at every dr, the finest
against Kingery-Bulmash (KB) and Henrych (1979), the change between the two
finest runs, the arrival (10 % of peak) of the finest, its first-order
Richardson extrapolation 2 t(dr) - t(2 dr) and KB's. --variants DIRs (another
start, viscosity, CFL, burn rule) are listed against the finest RUN_DIR of
equal dr, or the finest if none. --png: peak overpressure and its difference
against KB versus Z, with the runs' Lagrangian zone-peak curves.
"""
import argparse
import csv
import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import lagrangian_1d as lag  # noqa: E402
import v4_kb  # noqa: E402

import numpy as np  # noqa: E402


def load(run_dir):
    info = json.load(open(os.path.join(run_dir, "run.json")))
    rows = list(csv.DictReader(open(os.path.join(run_dir, "gauges.csv"))))
    for r in rows:
        for k, v in r.items():
            try:
                r[k] = float(v)
            except ValueError:
                pass
    profile = list(csv.DictReader(open(os.path.join(run_dir, "peak_profile.csv"))))
    return {"dir": run_dir, "info": info, "rows": rows, "profile": profile}


def label(run):
    i = run["info"]
    s = f"{i['start']} dr {i['dr_air_m'] * 1e3:g} mm"
    extra = []
    if i.get("beta_burn"):
        extra.append("beta burn")
    if (i["c_quad"], i["c_lin"]) != (2.0, 0.25):
        extra.append(f"Q {i['c_quad']:g}/{i['c_lin']:g}")
    if i["cfl"] != 0.5:
        extra.append(f"CFL {i['cfl']:g}")
    if i.get("merge", {}).get("frac", 0.5) == 0:
        extra.append("no merge")
    if abs(i["dr_charge_m"] - i["dr_air_m"]) > 0.05 * i["dr_air_m"]:
        extra.append(f"charge dr {i['dr_charge_m'] * 1e3:.3g} mm")
    if i.get("r_out_m", 1.6) != 1.6:
        extra.append(f"r_out {i['r_out_m']:g} m")
    return s + (" (" + ", ".join(extra) + ")" if extra else "")


def front_fit(t, y, skip=3.0, width=20.0):
    """Post-shock pressure extrapolated back to the shock: a quadratic in t fitted
    to y = p - p0 over [t_peak + skip rise, t_peak + (skip + width) rise] (rise =
    t_peak - t(10 % of peak)), evaluated at the 50 % crossing. It filters the
    zone-to-zone ringing the quadratic viscosity leaves behind the shock."""
    ip = int(np.argmax(y))
    pk = y[ip]

    def cross(level):
        k = int(np.flatnonzero(y > level)[0])
        return t[k - 1] + (level - y[k - 1]) / (y[k] - y[k - 1]) * (t[k] - t[k - 1])

    t10, t50 = cross(0.1 * pk), cross(0.5 * pk)
    rise = t[ip] - t10
    sel = (t >= t[ip] + skip * rise) & (t <= t[ip] + (skip + width) * rise)
    return float(np.polyval(np.polyfit(t[sel] - t50, y[sel], 2), 0.0))


def front_fits(run):
    h = np.load(os.path.join(run["dir"], "histories.npz"))
    return [front_fit(h["t"], h["p"][:, i] - lag.P0) for i in range(h["p"].shape[1])]


def pct(x):
    return f"{100 * x:+.1f} %"


def table(runs, variants):
    runs = sorted(runs, key=lambda r: -r["info"]["dr_air_m"])
    fine, second = runs[-1], runs[-2] if len(runs) > 1 else None
    drs = " | ".join(f"{r['info']['dr_air_m'] * 1e3:g} mm" for r in runs)
    print(f"Gauge peak overpressure [kPa], start {fine['info']['start']}, dr_air = {drs}:\n")
    print(f"| Z | R [m] | KB [kPa] | {drs} | finest vs KB | two finest | Henrych [kPa] (vs KB) |"
          f" finest vs Henrych | arrival finest / extrap. / KB [ms] | extrap. vs KB |")
    print("|" + "---|" * (9 + len(runs)))
    for i, row in enumerate(fine["rows"]):
        peaks = " | ".join(f"{r['rows'][i]['peak_Pa'] / 1e3:.1f}" for r in runs)
        d2 = (row["peak_Pa"] / second["rows"][i]["peak_Pa"] - 1) if second else math.nan
        t_ext = 2 * row["arrival_10pct_s"] - second["rows"][i]["arrival_10pct_s"] if second else math.nan
        print(f"| {row['Z']:g} | {row['R_m']:.4f} | {row['kb_peak_Pa'] / 1e3:.1f} | {peaks} | "
              f"{pct(row['peak_vs_kb'])} | {pct(d2)} | {row['henrych_peak_Pa'] / 1e3:.1f} "
              f"({pct(row['henrych_vs_kb'])}) | {pct(row['peak_vs_henrych'])} | "
              f"{row['arrival_10pct_s'] * 1e3:.4f} / {t_ext * 1e3:.4f} / {row['kb_arrival_s'] * 1e3:.4f} | "
              f"{pct(t_ext / row['kb_arrival_s'] - 1)} |")
    print("\nPeak measures [kPa] of the two finest runs (gauge max p / gauge max p+q / the zone"
          " that started at R: its max p / front fit of the gauge history):\n")
    print("| Z | " + " | ".join(f"{r['info']['dr_air_m'] * 1e3:g} mm" for r in runs[-2:]) + " |")
    print("|---|" + "---|" * len(runs[-2:]))
    fits = [front_fits(r) for r in runs[-2:]]
    for i, row in enumerate(fine["rows"]):
        cells = []
        for r, f in zip(runs[-2:], fits):
            g = r["rows"][i]
            cells.append(f"{g['peak_Pa'] / 1e3:.1f} / {g['peak_p_plus_q_Pa'] / 1e3:.1f} / "
                         f"{g['lagrangian_zone_peak_Pa'] / 1e3:.1f} / {f[i] / 1e3:.1f}")
        print(f"| {row['Z']:g} | " + " | ".join(cells) + " |")
    print("\nShock-speed consistency of the finest run: time between gauges from the arrivals"
          " against the Rankine-Hugoniot speeds of the gauge peaks (ideal gas 1.4, trapezoid):\n")
    c0 = math.sqrt(lag.GAMMA_AIR * lag.P0 / lag.RHO_AIR)

    def speed(row):
        g = lag.GAMMA_AIR
        return c0 * math.sqrt(1.0 + (g + 1.0) / (2.0 * g) * row["peak_Pa"] / lag.P0)

    print("| Z interval | from arrivals [us] | from peaks [us] | difference |")
    print("|---|---|---|---|")
    for a_, b_ in zip(fine["rows"][:-1], fine["rows"][1:]):
        dt_a = b_["arrival_10pct_s"] - a_["arrival_10pct_s"]
        dt_p = (b_["R_m"] - a_["R_m"]) * 0.5 * (1.0 / speed(a_) + 1.0 / speed(b_))
        print(f"| {a_['Z']:g}-{b_['Z']:g} | {dt_a * 1e6:.1f} | {dt_p * 1e6:.1f} | {pct(dt_p / dt_a - 1)} |")
    print("\nRuns:\n")
    print("| run | zones | steps | merges | wall [s] | energy error / charge energy |")
    print("|---|---|---|---|---|---|")
    for r in runs + variants:
        i = r["info"]
        print(f"| {label(r)} | {i['zones']} | {i['steps']} | {i.get('merges', 0)} | {i['wall_s']:.0f} |"
              f" {i['energy_error_rel_charge']:.1e} |")
    if variants:
        print("\nVariants: change of the gauge peak (max p) / of the front fit against the run of"
              " the same dr above (or the finest):\n")
        zs = " | ".join(f"Z {row['Z']:g}" for row in fine["rows"])
        print(f"| variant | {zs} | arrival shift, Z = 5 |")
        print("|" + "---|" * (2 + len(fine["rows"])))
        for v in variants:
            ref = next((r for r in runs if r["info"]["dr_air_m"] == v["info"]["dr_air_m"]), fine)
            fv, fr = front_fits(v), front_fits(ref)
            d = " | ".join(f"{100 * (a['peak_Pa'] / b['peak_Pa'] - 1):+.1f} / {100 * (x / y - 1):+.1f}"
                           for a, b, x, y in zip(v["rows"], ref["rows"], fv, fr))
            dt = v["rows"][-1]["arrival_10pct_s"] - ref["rows"][-1]["arrival_10pct_s"]
            print(f"| {label(v)} vs {ref['info']['dr_air_m'] * 1e3:g} mm | {d} | {dt * 1e6:+.2f} us |")


def figure(runs, variants, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    runs = sorted(runs, key=lambda r: -r["info"]["dr_air_m"])
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 7.5), sharex=True,
                                      gridspec_kw={"height_ratios": [1.3, 1]})
    zs = [0.5 * (5.2 / 0.5) ** (i / 200) for i in range(201)]
    kb = [v4_kb.overpressure(z) for z in zs]
    top.plot(zs, [k / 1e3 for k in kb], "k-", lw=1.5, label="Kingery-Bulmash")
    hen = [lag.henrych(z) for z in zs]
    top.plot(zs, [h / 1e3 for h in hen], "k--", lw=1, label="Henrych (1979)")
    bottom.plot(zs, [100 * (h / k - 1) for h, k in zip(hen, kb)], "k--", lw=1, label="Henrych")
    colors = plt.cm.viridis([0.15 + 0.7 * i / max(1, len(runs) - 1) for i in range(len(runs))])
    for run, col in zip(runs, colors):
        prof = [p for p in run["profile"] if p["material"] == "air" and 0.5 <= float(p["Z"]) <= 5.2]
        z = [float(p["Z"]) for p in prof]
        pk = [float(p["peak_overpressure_Pa"]) for p in prof]
        top.plot(z, [p / 1e3 for p in pk], "-", color=col, lw=0.8)
        bottom.plot(z, [100 * (p / v4_kb.overpressure(zz) - 1) for p, zz in zip(pk, z)], "-",
                    color=col, lw=0.8)
        zr = [r["Z"] for r in run["rows"]]
        bottom.plot(zr, [100 * r["peak_vs_kb"] for r in run["rows"]], "o", color=col, mfc="none",
                    label=f"gauges, {label(run)}")
    for v, m in zip(variants, "s^vdx+*"):
        bottom.plot([r["Z"] for r in v["rows"]], [100 * r["peak_vs_kb"] for r in v["rows"]], m,
                    mfc="none", color="tab:red", ms=5, label=label(v))
    top.set_xscale("log")
    top.set_yscale("log")
    top.set_ylabel("peak incident overpressure [kPa]")
    top.set_title("V4 model (JWL TNT 13.05 g + ideal-gas air), 1D Lagrangian reference")
    top.legend(fontsize=8, title="lines: Lagrangian zone peaks", title_fontsize=8)
    for level in (-10, 10):
        bottom.axhline(level, color="grey", ls=":", lw=0.8)
    bottom.axhline(0, color="k", lw=0.6)
    bottom.set_xlabel("Z [m/kg^(1/3)]")
    bottom.set_ylabel("difference vs KB [%]")
    bottom.set_ylim(-20, 15)
    bottom.legend(fontsize=6, ncol=2)
    bottom.set_xticks([0.5, 0.75, 1, 1.5, 2, 3, 4, 5])
    bottom.set_xticklabels(["0.5", "0.75", "1", "1.5", "2", "3", "4", "5"])
    fig.tight_layout()
    fig.savefig(png, dpi=90)
    print(f"\nwrote {png} ({os.path.getsize(png) / 1e3:.0f} kB)")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--variants", nargs="*", default=[])
    ap.add_argument("--png")
    ap.add_argument("--fig-variants", nargs="*", default=None,
                    help="variants drawn in the figure (default: all --variants)")
    a = ap.parse_args()
    runs = [load(d) for d in a.runs]
    variants = [load(d) for d in a.variants]
    table(runs, variants)
    if a.png:
        shown = variants if a.fig_variants is None else [load(d) for d in a.fig_variants]
        figure(runs, shown, a.png)


if __name__ == "__main__":
    main()
