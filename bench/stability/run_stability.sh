#!/usr/bin/env bash
# The stability suite of issue 7 (solver half): builds the two programs, runs
# the CFL sweep and the hard Riemann problems, and plots the stability map.
# Writes bench/stability/results/{cfl_runs,cfl_limits,riemann}.csv and
# stability_map.png. About 2 min on two loaded cores once built.
#
# Usage: bench/stability/run_stability.sh [build-dir]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
build="${1:-$root/build}"
results="$here/results"
export OMP_WAIT_POLICY=passive

cmake --build "$build" -j2 --target stability_cfl_sweep stability_riemann_suite
mkdir -p "$results"
"$build/bench/stability/stability_cfl_sweep" --out "$results"
status=0
"$build/bench/stability/stability_riemann_suite" --out "$results" || status=$?
/usr/bin/python3 "$here/plot_map.py" "$results"
if [ "$status" -ne 0 ]; then
  echo "run_stability.sh: a hard Riemann problem failed silently (see $results/riemann.csv)" >&2
fi
exit "$status"
