#!/bin/bash
# V6 (T §4.4.2) benchmarks: (a) CFDMP vs pure MPM, (b) work-precision against a
# fine pure-FDM reference, (c) coupling overhead share over inproc / ipc / tcp.
# Usage: bench/coupler/run_v6.sh [--build DIR] --out DIR [--parts a,b,c] [--h-a MM]
#          [--h-list MM,MM,...] [--h-ref MM] [--h-c MM] [--end S] [--charge tnt|gas] [--threads N]
# Needs the targets coupler, fdm_solver, mpm_solver. Writes DIR/v6_runs.csv,
# DIR/v6_bench.json, DIR/v6_*.png; a second call into the same DIR adds runs and
# skips those already measured. bench/README.md has the measured figures.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out=""
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  [[ "${args[i]}" == "--out" ]] && out="${args[i + 1]}"
done
[[ -n "$out" ]] || { echo "usage: $0 --out DIR [options]" >&2; exit 2; }
/usr/bin/python3 "$here/v6_bench.py" "$@"
/usr/bin/python3 "$here/plot_v6.py" "$out"
