#!/usr/bin/env bash
# The dormant FSI zone's saving (docs/coupler.md): runs a cfdmp scene with
# zones.mpm.activation_pressure (dormant) and without it (always on), one after
# the other in one call, one OpenMP thread per solver (both solvers are threads
# of the coupler and run concurrently), and prints each run's wall time, CPU time
# (user + system of the coupler process, i.e. the work of both solvers), steps,
# activation time and audit, and the ratios.
# Usage: bench/coupler/dormant_saving.sh [build-dir] [scene] [out-dir]
set -euo pipefail
build_dir=${1:-build}
scene=${2:-bench/coupler/cfdmp_blast_2d_far.yaml}
out=${3:-${build_dir}/dormant_saving}
mkdir -p "${out}"
sed -E 's/, *activation_pressure: *[^,}]+//' "${scene}" > "${out}/always_on.yaml"
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
TIMEFORMAT=%U+%S
{ time "${build_dir}/coupler/coupler" run "${scene}" --out "${out}/dormant" --overwrite \
  2>/dev/null; } 2> "${out}/dormant.cpu"
{ time "${build_dir}/coupler/coupler" run "${out}/always_on.yaml" --out "${out}/always_on" \
  --overwrite 2>/dev/null; } 2> "${out}/always_on.cpu"
/usr/bin/python3 - "${out}" <<'PY'
import json, os, sys
out = sys.argv[1]
rows, cpu = {}, {}
print(f"load average: {os.getloadavg()[0]:.2f}")
print(f"{'run':<10}{'wall s':>9}{'cpu s':>9}{'steps':>7}{'mpm adv s':>10}{'woken at s':>12}"
      f"{'mass err':>11}{'energy err':>11}")
for name in ("dormant", "always_on"):
    s = json.load(open(os.path.join(out, name, "summary.json")))
    d = s["details"]
    rows[name] = s["wall_time_s"]
    cpu[name] = eval(open(os.path.join(out, name + ".cpu")).read().strip())
    woken = d["activation"]["time_s"]
    print(f"{name:<10}{s['wall_time_s']:>9.1f}{cpu[name]:>9.1f}{s['steps']:>7}"
          f"{d['timing']['mpm_advance_seconds']:>10.1f}"
          f"{woken if woken is not None else float('nan'):>12.3e}"
          f"{s['conservation']['mass']['relative_error']:>11.2e}"
          f"{s['conservation']['energy']['relative_error']:>11.2e}")
print(f"dormant / always-on: wall time {rows['dormant'] / rows['always_on']:.3f}, "
      f"cpu time {cpu['dormant'] / cpu['always_on']:.3f}")
PY
