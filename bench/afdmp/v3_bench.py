#!/usr/bin/python3
"""V3 (METHOD.md; T §3.4.2, Figs. 3.8-3.9) benchmark, driven by bench/afdmp/run_v3.sh.

For each cell size h: configs/afdmp_blast_2d.yaml re-gridded, run by AFDMP
(`coupler run`, solvers embedded, so the process's peak RSS is the whole run's)
and by pure MPM (`mpm_solver run` on the same scene with solver.method: mpm, the
same particles), each under /usr/bin/time -v: wall time and peak RSS. Then the
interface measures of tests/verification/afdmp/v3_interface.hpp at 10, 50 and
90 us (afdmp_v3_metrics). Results: <out>/v3_runs.csv (one line per run),
<out>/v3_interface.csv (one line per run, source and time); plots by plot_v3.py.
A second call into the same <out> skips runs already in v3_runs.csv.
"""
import argparse
import csv
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMES = (1e-5, 5e-5, 9e-5)
PRODUCTS = ("1", "tnt", "air")  # products index and name, air name (scene materials: air, tnt)
RUN_FIELDS = ["h_mm", "method", "wall_s", "peak_rss_mib", "user_s", "steps", "status"]
INTERFACE_FIELDS = ["h_mm", "method", "source", "time_s", "mean_radius_m", "anisotropy",
                    "air_inside", "products_outside"]


def scene_text(method, cells):
    text = open(os.path.join(ROOT, "configs", "afdmp_blast_2d.yaml")).read()
    text = text.replace("cells: [500, 500, 1]", f"cells: [{cells}, {cells}, 1]")
    text = re.sub(r"name: afdmp_blast_2d", f"name: v3_{method}_{cells}", text, count=1)
    if method == "mpm":
        text = text.replace("method: afdmp", "method: mpm").replace("  afdmp: {start: mpm}\n", "")
    return text


def timed(command, env):
    """Runs `command` under /usr/bin/time -v; returns (wall s, peak RSS MiB, user s)."""
    done = subprocess.run(["/usr/bin/time", "-v"] + command, env=env, capture_output=True,
                          text=True)
    if done.returncode != 0:
        sys.stderr.write(done.stdout + done.stderr)
        raise SystemExit(f"v3_bench: {' '.join(command)} failed ({done.returncode})")
    wall = re.search(r"Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): (\S+)", done.stderr).group(1)
    seconds = 0.0
    for part in wall.split(":"):
        seconds = 60 * seconds + float(part)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", done.stderr).group(1))
    user = float(re.search(r"User time \(seconds\): (\S+)", done.stderr).group(1))
    return seconds, rss / 1024.0, user


def steps_of(run_dir, method):
    import json
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    if method == "mpm":
        return summary.get("steps", "")
    return sum(p.get("steps", 0) for p in summary["details"]["afdmp"]["phases"])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", required=True)
    parser.add_argument("--h-list", default="5,2.5", help="cell sizes in mm")
    parser.add_argument("--threads", default="1", help="OMP_NUM_THREADS of every run")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS=args.threads, OMP_WAIT_POLICY="passive")
    runs_csv = os.path.join(args.out, "v3_runs.csv")
    interface_csv = os.path.join(args.out, "v3_interface.csv")
    done = set()
    if os.path.exists(runs_csv):
        done = {(r["h_mm"], r["method"]) for r in csv.DictReader(open(runs_csv))}
    for h_mm in [float(h) for h in args.h_list.split(",")]:
        cells = round(500 / h_mm)
        for method in ("afdmp", "mpm"):
            key = (f"{h_mm:g}", method)
            if key in done:
                continue
            scene = os.path.join(args.out, f"v3_{method}_h{h_mm:g}mm.yaml")
            run_dir = os.path.join(args.out, f"v3_{method}_h{h_mm:g}mm")
            open(scene, "w").write(scene_text(method, cells))
            program = (os.path.join(args.build, "coupler", "coupler") if method == "afdmp"
                       else os.path.join(args.build, "mpm_solver", "mpm_solver"))
            print(f"V3 h = {h_mm:g} mm {method} ...", flush=True)
            wall, rss, user = timed([program, "run", scene, "--out", run_dir, "--overwrite"], env)
            print(f"  wall {wall:.1f} s, peak RSS {rss:.0f} MiB", flush=True)
            metrics = subprocess.run(
                [os.path.join(args.build, "tests", "verification", "afdmp", "afdmp_v3_metrics"),
                 method, run_dir, repr(h_mm * 1e-3)] + list(PRODUCTS) + [repr(t) for t in TIMES],
                capture_output=True, text=True, check=True).stdout
            new_runs = not os.path.exists(runs_csv)
            with open(runs_csv, "a", newline="") as f:
                w = csv.DictWriter(f, RUN_FIELDS)
                if new_runs:
                    w.writeheader()
                w.writerow({"h_mm": f"{h_mm:g}", "method": method, "wall_s": f"{wall:.2f}",
                            "peak_rss_mib": f"{rss:.1f}", "user_s": f"{user:.2f}",
                            "steps": steps_of(run_dir, method), "status": "completed"})
            new_interface = not os.path.exists(interface_csv)
            with open(interface_csv, "a", newline="") as f:
                w = csv.DictWriter(f, INTERFACE_FIELDS)
                if new_interface:
                    w.writeheader()
                for row in csv.DictReader(metrics.splitlines()):
                    w.writerow(dict(row, h_mm=f"{h_mm:g}", method=method))
                    print(f"  {row['source']} t = {float(row['time_s']) * 1e6:.0f} us: anisotropy "
                          f"{float(row['anisotropy']):.4f}, air inside {float(row['air_inside']):.2e}"
                          f", products outside {float(row['products_outside']):.2e}", flush=True)


if __name__ == "__main__":
    main()
