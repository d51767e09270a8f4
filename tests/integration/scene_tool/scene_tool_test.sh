#!/usr/bin/env bash
# The scene tool as a user runs it: validate scenes, refuse broken ones before
# writing anything, write the initial state in the documented layout, never
# overwrite a finished run by mistake, and plot it.
# Usage: scene_tool_test.sh <mpfd_scene> <repository root>
set -uo pipefail
tool=$1
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0

check() {  # check <description> <command...>: passes if the command succeeds
  local what=$1
  shift
  if "$@"; then
    passes=$((passes + 1))
  else
    echo "FAILED: $what"
    failures=$((failures + 1))
  fi
}

# A valid scene is described, with the CJ state of its explosive.
"$tool" check "$root/configs/demo.yaml" >"$work/check.out" 2>&1
check "check exits 0 on the demo scene" test $? -eq 0
check "check reports the TNT CJ pressure" grep -q "p = 20.98 GPa" "$work/check.out"
check "check says the scene is valid" grep -q "demo.yaml: valid" "$work/check.out"

# A broken scene: exit 1, every message names the file and line, nothing written.
broken="$root/tests/unit/common/config/scenes/many_errors.yaml"
"$tool" init "$broken" --out "$work/never" >"$work/broken.out" 2>&1
check "init exits 1 on a broken scene" test $? -eq 1
check "the error names the file and a line" grep -qE "many_errors.yaml:[0-9]+:[0-9]+: " "$work/broken.out"
check "a broken scene writes nothing" test ! -e "$work/never"

# The initial state in the layout of docs/output.md.
"$tool" init "$root/configs/demo.yaml" --out "$work/run" >"$work/init.out" 2>&1
check "init exits 0" test $? -eq 0
for f in summary.json cells.xmf snapshots/snapshot_000000.h5 gauges.csv gauges.h5; do
  check "init writes $f" test -s "$work/run/$f"
done
check "summary says completed" grep -q '"status": "completed"' "$work/run/summary.json"
check "gauge CSV header has units" grep -q '^time\[s\],near.density\[kg/m^3\]' "$work/run/gauges.csv"
check "no partial files are left" test -z "$(find "$work/run" -name '*.tmp')"

# A second run into the same folder is refused and the first run is kept.
before=$(sha256sum "$work/run/summary.json")
"$tool" init "$root/configs/demo.yaml" --out "$work/run" >"$work/again.out" 2>&1
check "init refuses a folder that holds a run" test $? -eq 1
check "the refusal says how to overwrite" grep -q -- "--overwrite" "$work/again.out"
check "the earlier run is untouched" test "$before" = "$(sha256sum "$work/run/summary.json")"

# A bad flag is a usage error naming it.
"$tool" init "$root/configs/demo.yaml" --out "$work/x" --bogus >"$work/flag.out" 2>&1
check "an unknown flag exits non-zero" test $? -ne 0
check "the unknown flag is named" grep -q -- "--bogus" "$work/flag.out"

# The printed schema is the checked-in reference.
"$tool" schema >"$work/schema.md"
check "schema matches configs/SCENE-REFERENCE.md" cmp -s "$work/schema.md" "$root/configs/SCENE-REFERENCE.md"

# Plots from the documented layout.
/usr/bin/python3 "$root/tools/plot_run.py" "$work/run" >"$work/plot.out" 2>&1
check "plot_run.py succeeds" test $? -eq 0
check "profiles.png is written" test -s "$work/run/plots/profiles.png"

echo "$passes passed, $failures failed"
test "$failures" -eq 0
