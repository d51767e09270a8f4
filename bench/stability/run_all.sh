#!/usr/bin/env bash
# The whole stability suite of issue 7 (docs/stability.md): the CFL map and hard
# Riemann problems (run_stability.sh), then the long quiet runs, extreme
# deformation, coupling under stress and random scenes (run_stability_runs.sh).
# Both halves run even if the first flags a defect; exits 1 if either did.
#
# Usage: bench/stability/run_all.sh [build-dir]   (default: build)
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$(cd "$here/../.." && pwd)/build}"
status=0
"$here/run_stability.sh" "$build" || status=1
"$here/run_stability_runs.sh" "$build" || status=1
echo "run_all.sh: results in $here/results ($([ $status -eq 0 ] && echo 'no defect flagged' || echo 'defects flagged above'))"
exit "$status"
