#!/usr/bin/env bash
# Runs the FDM benchmarks of the issue and prints them against its targets:
#  (a) work-precision on Sod's tube (bench/fdm/sod_work_precision, CFL 0.3 /
#      0.5 / 0.8, N = 100 ... 3200) -> fdm_work_precision.csv + .png;
#  (b) throughput and memory per cell of the 128^3 blast (bench/fdm/blast128.yaml,
#      --full-grid) on 1 and 2 threads, best of 3 alternating runs each;
#  (c) the disturbed-region saving: bench/fdm/quiet_box.yaml with and without
#      --full-grid on one thread (less exposed to other jobs on a shared
#      machine), wall-time ratio and a bitwise comparison of the final snapshots.
# Writes OUT/fdm_bench.json with every figure and the load average at start.
# Needs a build with tests on (the default): fdm_solver and sod_work_precision.
# Takes about 5 minutes on 2 idle cores.
# Usage: bench/run_fdm.sh [build-dir] [out-dir]
set -euo pipefail
build_dir=${1:-build}
out=${2:-${build_dir}/fdm_bench}
src=$(cd "$(dirname "$0")/.." && pwd)
solver="${build_dir}/fdm_solver/fdm_solver"
work_precision="${build_dir}/bench/fdm/sod_work_precision"
for program in "${solver}" "${work_precision}"; do
  [[ -x ${program} ]] || { echo "run_fdm.sh: ${program} not built" >&2; exit 1; }
done
mkdir -p "${out}"
load_at_start=$(cut -d' ' -f1-3 /proc/loadavg)

echo "== (a) work-precision, Sod's tube" >&2
"${work_precision}" --out "${out}/fdm_work_precision.csv" --repeats 3 >"${out}/work_precision.log"
/usr/bin/python3 "${src}/tools/plot_work_precision.py" "${out}/fdm_work_precision.csv" \
  "${out}/fdm_work_precision.png" >/dev/null

run() {  # run NAME SCENE ARGS...: one fdm_solver run into OUT/NAME, its log beside it
  local name=$1 scene=$2
  shift 2
  echo "== ${name}" >&2
  "${solver}" run "${src}/bench/fdm/${scene}" --out "${out}/${name}" --overwrite "$@" \
    >"${out}/${name}.log" 2>&1
}
for rep in 1 2 3; do  # alternating, so that a burst of other load hits both alike
  run "blast128_t1_r${rep}" blast128.yaml --full-grid --threads 1
  run "blast128_t2_r${rep}" blast128.yaml --full-grid --threads 2
done
run quiet_box_skip quiet_box.yaml --threads 1
run quiet_box_full quiet_box.yaml --threads 1 --full-grid

/usr/bin/python3 - "${out}" "${load_at_start}" <<'PY'
import glob, json, os, sys
import h5py
import numpy as np

out, load = sys.argv[1], [float(v) for v in sys.argv[2].split()]
summary = lambda name: json.load(open(os.path.join(out, name, "summary.json")))
doc = {"load_average_at_start": {"1min": load[0], "5min": load[1], "15min": load[2]},
       "cores": os.cpu_count()}

# (a) work-precision
rows = np.atleast_1d(np.genfromtxt(os.path.join(out, "fdm_work_precision.csv"), delimiter=",",
                                   names=True))
wp = {}
for cfl in np.unique(rows["cfl"]):
    r = np.sort(rows[rows["cfl"] == cfl], order="cells")
    order = -np.polyfit(np.log(r["cells"]), np.log(r["l1_density"]), 1)[0]
    wp[f"{cfl:g}"] = {c: r[c].tolist() for c in ("cells", "steps", "wall_s", "l1_density",
                                                  "l1_velocity", "l1_pressure")}
    wp[f"{cfl:g}"].update(cells=r["cells"].astype(int).tolist(),
                          steps=r["steps"].astype(int).tolist(), fitted_order_density=order)
doc["work_precision"] = {"csv": "fdm_work_precision.csv", "plot": "fdm_work_precision.png",
                         "by_cfl": wp}

# (b) throughput and memory, 128^3 blast, every cell every step
tp = {}
for threads in (1, 2):
    runs = [summary(f"blast128_t{threads}_r{rep}") for rep in (1, 2, 3)]
    rates = [r["rates"]["cell_updates_per_second"] for r in runs]
    s = runs[int(np.argmax(rates))]
    rate = max(rates)
    tp[f"threads_{threads}"] = {
        "cell_updates_per_second": rate, "all_runs_cell_updates_per_second": rates,
        "sweep_cell_updates_per_second": 6 * rate,  # one step of (2-52) = 6 half-step sweeps
        "steps": s["steps"], "solver_time_s": s["details"]["solver_time_s"],
        "peak_memory_bytes_per_cell": max(r["details"]["peak_memory_bytes_per_cell"]
                                          for r in runs)}
tp["speedup_2_threads"] = (tp["threads_2"]["cell_updates_per_second"]
                           / tp["threads_1"]["cell_updates_per_second"])
doc["blast128"] = tp

# (c) disturbed-region saving
skip, full = summary("quiet_box_skip"), summary("quiet_box_full")
def last_snapshot(name):
    return sorted(glob.glob(os.path.join(out, name, "snapshots", "snapshot_*.h5")))[-1]
with h5py.File(last_snapshot("quiet_box_skip"), "r") as a, \
        h5py.File(last_snapshot("quiet_box_full"), "r") as b:
    fields = sorted(a["cells"].keys())
    identical = (fields == sorted(b["cells"].keys()) and a.attrs["step"] == b.attrs["step"]
                 and a.attrs["time"] == b.attrs["time"]
                 and all(np.array_equal(a["cells"][f][...], b["cells"][f][...]) for f in fields))
cells_steps = full["details"]["cells"] * full["steps"]
doc["quiet_box"] = {
    "threads": 1, "cells": full["details"]["cells"], "steps": full["steps"],
    "solver_time_s": {"disturbed_region": skip["details"]["solver_time_s"],
                      "full_grid": full["details"]["solver_time_s"]},
    "wall_time_s": {"disturbed_region": skip["wall_time_s"], "full_grid": full["wall_time_s"]},
    "solver_time_ratio_full_over_region": (full["details"]["solver_time_s"]
                                           / skip["details"]["solver_time_s"]),
    "updated_fraction_of_cell_steps": skip["details"]["cell_updates"] / cells_steps,
    "final_snapshots_bitwise_identical": bool(identical), "compared_fields": fields}
json.dump(doc, open(os.path.join(out, "fdm_bench.json"), "w"), indent=1)

# table
yes = lambda ok: "yes" if ok else "NO"
print(f"load average at start: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f} on {os.cpu_count()} cores")
print("work-precision, Sod to t = 0.2: L1 of density, solver wall time (fdm_work_precision.png)")
print(f"  {'CFL':<5}{'L1 N=100':>11}{'L1 N=3200':>11}{'order':>7}{'wall N=3200':>13}")
for cfl, w in wp.items():
    print(f"  {cfl:<5}{w['l1_density'][0]:>11.3e}{w['l1_density'][-1]:>11.3e}"
          f"{w['fitted_order_density']:>7.2f}{w['wall_s'][-1]:>11.3f} s")
def row(case, measured, target="", met="-"):
    print(f"{case:<66}{measured:>14}{target:>12}  {met}")
row("case", "measured", "target", "met")
for threads in (1, 2):
    rate = tp[f"threads_{threads}"]["cell_updates_per_second"] / 1e6
    name = f"blast 128^3, {threads} thread{'s' if threads > 1 else ''}, best of 3"
    if threads == 1:
        row(f"{name}: cell-updates/s (whole steps)", f"{rate:.2f} M/s", ">= 10 M/s", yes(rate >= 10.0))
    else:
        row(f"{name}: cell-updates/s (whole steps)", f"{rate:.2f} M/s")
    row(f"{name}: half-step sweep updates/s (6 x)", f"{6 * rate:.2f} M/s")
mem = tp["threads_1"]["peak_memory_bytes_per_cell"]
row("blast 128^3, peak RSS / cells (1 thread, largest)", f"{mem:.1f} B/cell", "<= 200 B",
    yes(mem <= 200))
q = doc["quiet_box"]
ratio = q["solver_time_ratio_full_over_region"]
row("quiet box 192^3, 1 thread: solver time full/region", f"{ratio:.2f} x", "> 1", yes(ratio > 1))
row("quiet box 192^3: cell-steps updated with region",
    f"{100 * q['updated_fraction_of_cell_steps']:.1f} %")
row("quiet box 192^3: final snapshots bitwise equal", str(bool(identical)), "identical",
    yes(identical))
print(f"written: {os.path.join(out, 'fdm_bench.json')}")
PY
