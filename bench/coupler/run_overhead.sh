#!/usr/bin/env bash
# Coupling overhead share of `coupler run` (issue 5): for the 1D Sod case
# (configs/cfdmp_sod_1d.yaml) and the 2D case (bench/coupler/cfdmp_2d_overhead.yaml,
# 200 x 100 cells, 48 000 particles), solvers as threads (inproc) and as child
# processes (ipc), one OpenMP thread per solver. Reads summary.json's "timing":
#   share = 1 - sum(slower solver's Advance wall) / sum(step wall).
# Runs alternate (case x transport x build, `repeats` rounds) so that the
# machine's load hits all alike; the table prints the median of each. With a
# second build folder (e.g. one of the previous commit) both are measured.
# Usage: bench/coupler/run_overhead.sh [build-dir] [out.csv] [repeats] [baseline-build-dir]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "${here}/../.." && pwd)
builds=("$(cd "${1:-build}" && pwd)")
out=${2:-${builds[0]}/coupler_overhead.csv}
repeats=${3:-3}
[[ -n ${4:-} ]] && builds+=("$(cd "$4" && pwd)")
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive
declare -A scenes=([sod_1d]="${root}/configs/cfdmp_sod_1d.yaml"
                   [cfdmp_2d]="${here}/cfdmp_2d_overhead.yaml")
echo "build,case,transport,round,steps,step_wall_s,advance_wall_s,share" >"${out}"
for round in $(seq 1 "${repeats}"); do
  for case in sod_1d cfdmp_2d; do
    for transport in inproc ipc; do
      for b in "${!builds[@]}"; do
        build=${builds[$b]}
        label=$([[ $b == 0 ]] && echo this || echo baseline)
        flags=()
        [[ ${transport} == ipc ]] && flags=(--processes
          --fdm-program "${build}/fdm_solver/fdm_solver" --mpm-program "${build}/mpm_solver/mpm_solver")
        dir="${work}/${label}_${case}_${transport}"
        "${build}/coupler/coupler" run "${scenes[${case}]}" --out "${dir}" --overwrite "${flags[@]}" \
          >"${work}/log" 2>&1 || { cat "${work}/log"; exit 1; }
        /usr/bin/python3 - "${dir}/summary.json" "${label},${case},${transport},${round}" \
          >>"${out}" <<'PY'
import json, sys
doc = json.load(open(sys.argv[1]))
t = doc["details"]["timing"]
print(f"{sys.argv[2]},{doc['steps']},{t['step_seconds']:.6f},"
      f"{t['slower_advance_seconds']:.6f},{t['coupling_overhead_share']:.4f}")
PY
      done
    done
  done
done
/usr/bin/python3 - "${out}" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print(f"{'build':<9}{'case':<10}{'transport':<10}{'steps':>6}{'step wall':>12}{'advance':>12}"
      f"{'overhead/step':>15}{'share':>8}")
for build in dict.fromkeys(r["build"] for r in rows):
    for case in ("sod_1d", "cfdmp_2d"):
        for transport in ("inproc", "ipc"):
            sel = [r for r in rows if (r["build"], r["case"], r["transport"]) == (build, case, transport)]
            med = lambda k: statistics.median(float(r[k]) for r in sel)
            steps = int(sel[0]["steps"])
            per_step = statistics.median((float(r["step_wall_s"]) - float(r["advance_wall_s"])) / steps
                                         for r in sel)
            print(f"{build:<9}{case:<10}{transport:<10}{steps:>6}{med('step_wall_s') * 1e3:>9.1f} ms"
                  f"{med('advance_wall_s') * 1e3:>9.1f} ms{per_step * 1e3:>12.3f} ms{med('share'):>8.3f}")
PY
