#!/usr/bin/env bash
# mpm_solver run as a user runs it: a scene to its end in the documented
# layout with a balanced audit; a finished run is never overwritten by
# mistake; a scene for another method and a broken scene write nothing.
# Usage: mpm_run_test.sh <mpm_solver> <repository root>
set -uo pipefail
solver=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passes=0
failures=0
check() {
  local what=$1
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAILED: $what"; failures=$((failures + 1)); fi
}
json() {  # json FILE EXPR: prints a value from summary.json
  /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"
}

# Sod in MPM to its end.
"$solver" run "$root/configs/sod_mpm.yaml" --out "$work/sod" --threads 1 >"$work/sod.out" 2>&1
check "run exits 0" test $? -eq 0
for f in summary.json particles.xmf snapshots/snapshot_000000.h5 snapshots/snapshot_000010.h5 gauges.csv gauges.h5; do
  check "run writes $f" test -s "$work/sod/$f"
done
check "summary says completed" test "$(json "$work/sod/summary.json" 'd["status"]')" = completed
check "the run reached its end time" test "$(json "$work/sod/summary.json" 'd["time_s"]')" = 0.2
check "mass balances exactly" test "$(json "$work/sod/summary.json" 'abs(d["conservation"]["mass"]["relative_error"]) < 1e-15')" = True
check "momentum balances to 1e-12 (walls booked)" test "$(json "$work/sod/summary.json" 'abs(d["conservation"]["momentum_x"]["relative_error"]) < 1e-12')" = True
check "energy balances to 1 %" test "$(json "$work/sod/summary.json" 'abs(d["conservation"]["energy"]["relative_error"]) < 1e-2')" = True
check "a throughput is reported" test "$(json "$work/sod/summary.json" 'd["rates"]["particle_updates_per_second"] > 0')" = True
check "particle stress is written" grep -q "/particles/stress_xx" "$work/sod/particles.xmf"

# The same folder again: refused, the first run kept.
before=$(sha256sum "$work/sod/summary.json")
"$solver" run "$root/configs/sod_mpm.yaml" --out "$work/sod" >"$work/again.out" 2>&1
check "a finished run's folder is refused" test $? -eq 1
check "the refusal names --overwrite" grep -q -- "--overwrite" "$work/again.out"
check "the first run is untouched" test "$before" = "$(sha256sum "$work/sod/summary.json")"

# An FDM scene: refused before anything is written.
"$solver" run "$root/configs/sod.yaml" --out "$work/fdm" >"$work/fdm.out" 2>&1
check "an fdm scene exits 1" test $? -eq 1
check "the refusal names solver.method" grep -q "solver.method" "$work/fdm.out"
check "an fdm scene writes nothing" test ! -e "$work/fdm"

# A broken scene: exit 1, the file and line named, nothing written.
"$solver" run "$root/tests/unit/common/config/scenes/many_errors.yaml" --out "$work/broken" >"$work/broken.out" 2>&1
check "a broken scene exits 1" test $? -eq 1
check "the error names file and line" grep -qE "many_errors.yaml:[0-9]+:[0-9]+:" "$work/broken.out"
check "a broken scene writes nothing" test ! -e "$work/broken"

echo "$passes passed, $failures failed"
test "$failures" -eq 0
