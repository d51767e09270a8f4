#!/bin/bash
# The second half of the stability suite (docs/stability.md (part 2)): long quiet
# runs, extreme deformation, coupling under stress, randomised scenes.
# Usage: bench/stability/run_stability_runs.sh [BUILD_DIR] [OUT_DIR]
#   BUILD_DIR  default build (needs the targets fdm_solver, mpm_solver, coupler)
#   OUT_DIR    default bench/stability/results (CSV, PNG; not committed)
# Runs one after the other, each solver on 1 OpenMP thread; about 30 min on
# the shared 2-core machine. Exit status 1 when a case ends in NaN, a crash, a
# hang or a silent blow-up, or a drift or audit exceeds its stated bound.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-build}"
out="${2:-$here/results}"
mkdir -p "$out"
export OMP_WAIT_POLICY=passive
status=0
/usr/bin/python3 "$here/quiet_runs.py" "$build" "$out" --check || status=1
/usr/bin/python3 "$here/extreme_runs.py" "$build" "$out" --check || status=1
/usr/bin/python3 "$here/coupling_runs.py" "$build" "$out" --check || status=1
/usr/bin/python3 "$here/random_scenes.py" "$build" "$out" --seeds 0-59 --check || status=1
echo "results in $out: quiet_drift.csv quiet_summary.csv quiet_drift.png extreme_runs.csv" \
     "coupling_runs.csv random_scenes.csv"
exit $status
