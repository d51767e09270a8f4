#!/usr/bin/env bash
# fdm_solver run as a user runs it: a scene to its end in the documented
# layout with a balanced audit; a finished run is never overwritten by
# mistake; a broken scene writes nothing; a run that fails mid-way says so in
# summary.json and keeps what it wrote; bad flags are named.
# Usage: fdm_run_test.sh <fdm_solver> <repository root>
set -uo pipefail
solver=$1
root=$2
here=$(cd "$(dirname "$0")" && pwd)
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

# Sod to its end.
"$solver" run "$root/configs/sod.yaml" --out "$work/sod" >"$work/sod.out" 2>&1
check "run exits 0" test $? -eq 0
for f in summary.json cells.xmf snapshots/snapshot_000000.h5 snapshots/snapshot_000010.h5 gauges.csv gauges.h5; do
  check "run writes $f" test -s "$work/sod/$f"
done
check "summary says completed" test "$(json "$work/sod/summary.json" 'd["status"]')" = completed
check "the run reached its end time" test "$(json "$work/sod/summary.json" 'd["time_s"]')" = 0.2
check "mass balances to 1e-12" test "$(json "$work/sod/summary.json" 'abs(d["conservation"]["mass"]["relative_error"]) < 1e-12')" = True
check "energy balances to 1e-12" test "$(json "$work/sod/summary.json" 'abs(d["conservation"]["energy"]["relative_error"]) < 1e-12')" = True
check "a throughput is reported" test "$(json "$work/sod/summary.json" 'd["rates"]["cell_updates_per_second"] > 0')" = True
# Steps (~4 ms) are longer than gauge_interval (1 ms): a sample at every step.
steps=$(json "$work/sod/summary.json" 'd["steps"]')
check "gauges are sampled at every step" test "$(($(wc -l <"$work/sod/gauges.csv") - 1))" -ge "$steps"

# Two materials: the tracers are written as particles.
"$solver" run "$root/configs/jwl_air_tube.yaml" --out "$work/tube" >"$work/tube.out" 2>&1
check "the two-material tube runs" test $? -eq 0
check "its tracers are in particles.xmf" grep -q "/particles/position" "$work/tube/particles.xmf"

# The SSE2 and the default (AVX2 where the CPU has it) builds of the sweep kernel agree bit for bit.
blast="$root/tests/integration/fdm_run/kernel_blast.yaml"
MPFD_FDM_KERNEL=baseline "$solver" run "$blast" --out "$work/baseline" >"$work/baseline.out" 2>&1
check "the baseline kernel runs" test $? -eq 0
check "its summary names the baseline kernel" test "$(json "$work/baseline/summary.json" 'd["details"]["sweep_kernel"]')" = baseline
"$solver" run "$blast" --out "$work/default" >"$work/default.out" 2>&1
check "the default kernel runs" test $? -eq 0
check "both kernels give the same final snapshot, bit for bit" \
  /usr/bin/python3 -c "
import h5py, numpy, sys
a, b = (h5py.File(sys.argv[i] + '/snapshots/snapshot_000001.h5') for i in (1, 2))
names = []
a.visit(lambda n: names.append(n) if isinstance(a[n], h5py.Dataset) else None)
assert names, 'no datasets'
sys.exit(0 if all(numpy.array_equal(a[n][()], b[n][()]) for n in names) else 1)" "$work/baseline" "$work/default"

# The same folder again: refused, the first run kept.
before=$(sha256sum "$work/sod/summary.json")
"$solver" run "$root/configs/sod.yaml" --out "$work/sod" >"$work/again.out" 2>&1
check "a finished run's folder is refused" test $? -eq 1
check "the refusal names --overwrite" grep -q -- "--overwrite" "$work/again.out"
check "the first run is untouched" test "$before" = "$(sha256sum "$work/sod/summary.json")"

# A broken scene: exit 1, the file and line named, nothing written.
"$solver" run "$root/tests/unit/common/config/scenes/many_errors.yaml" --out "$work/broken" >"$work/broken.out" 2>&1
check "a broken scene exits 1" test $? -eq 1
check "the error names file and line" grep -qE "many_errors.yaml:[0-9]+:[0-9]+:" "$work/broken.out"
check "a broken scene writes nothing" test ! -e "$work/broken"

# A run that fails mid-way.
"$solver" run "$here/water_tension.yaml" --out "$work/tension" >"$work/tension.out" 2>&1
check "a failing run exits 1" test $? -eq 1
check "the error names the cell" grep -q "unphysical state in cell (" "$work/tension.out"
check "summary says failed" test "$(json "$work/tension/summary.json" 'd["status"]')" = failed
check "summary carries the error" test "$(json "$work/tension/summary.json" '"unphysical" in d["error"]')" = True
check "snapshots before the failure are kept" test -s "$work/tension/snapshots/snapshot_000000.h5"

# Bad flags.
"$solver" run "$root/configs/sod.yaml" --out "$work/x" --threads 0 >"$work/flag.out" 2>&1
check "--threads 0 is refused" test $? -ne 0
"$solver" run "$root/configs/nonexistent.yaml" --out "$work/y" >"$work/missing.out" 2>&1
check "a missing scene file is refused" test $? -ne 0
check "the missing file is named" grep -q "nonexistent.yaml" "$work/missing.out"

echo "$passes passed, $failures failed"
test "$failures" -eq 0
