#!/bin/bash
# V3 (METHOD.md; T §3.4.2) benchmark: AFDMP against pure MPM on the 2D TNT
# cylinder in air at several h: wall time and peak RSS (/usr/bin/time -v), and
# the interface measures at 10, 50 and 90 us (tests/verification/afdmp/v3_interface.hpp).
# Usage: bench/afdmp/run_v3.sh --out DIR [--build DIR] [--h-list 5,2.5,1] [--threads N]
# Needs the targets coupler, mpm_solver and afdmp_v3_metrics. Writes DIR/v3_runs.csv,
# DIR/v3_interface.csv and DIR/v3_{cost,interface,particles}.png; a second call
# into the same DIR adds the runs not yet measured. bench/README.md has the figures.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
out=""
args=("$@")
for ((i = 0; i < ${#args[@]}; i++)); do
  [[ "${args[i]}" == "--out" ]] && out="${args[i + 1]}"
done
[[ -n "$out" ]] || { echo "usage: $0 --out DIR [--build DIR] [--h-list MM,...] [--threads N]" >&2; exit 2; }
/usr/bin/python3 "$here/v3_bench.py" "$@"
/usr/bin/python3 "$here/plot_v3.py" "$out"
