#!/usr/bin/env bash
# `coupler run` with real solver processes: over ipc, over tcp on separate
# loopback addresses, a refused scene, a missing external solver, and a solver
# killed mid-run. Usage: coupler_run_test.sh COUPLER SOURCE_DIR
set -u
coupler=$1
source_dir=$2
scene=$source_dir/configs/cfdmp_sod_1d.yaml
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_WAIT_POLICY=passive
fail() { echo "FAIL: $*"; exit 1; }
status_of() { grep -o '"status": *"[a-z]*"' "$1/summary.json" | grep -o '[a-z]*"$' | tr -d '"'; }

# 1. child processes over ipc, recorded
"$coupler" run "$scene" --out "$work/ipc" --processes --record "$work/ipc.mpfdrec" 2> "$work/ipc.log" \
  || fail "ipc run: $(tail -1 "$work/ipc.log")"
[ "$(status_of "$work/ipc")" = completed ] || fail "ipc run: summary not completed"
[ -s "$work/ipc.mpfdrec" ] || fail "ipc run: no recording"
ls "$work/ipc/fdm/snapshots/"*.h5 "$work/ipc/mpm/snapshots/"*.h5 > /dev/null || fail "ipc run: no snapshots"

# 2. tcp, each solver on its own loopback address (127.0.0.1 if those cannot be bound)
port=$((20000 + $$ % 20000))
endpoints="fdm=tcp://127.0.0.2:$port,mpm=tcp://127.0.0.3:$((port + 1))"
if ! "$coupler" run "$scene" --out "$work/tcp" --processes --endpoints "$endpoints" 2> "$work/tcp.log"; then
  grep -q "cannot bind" "$work/tcp.log" || fail "tcp run: $(tail -1 "$work/tcp.log")"
  endpoints="fdm=tcp://127.0.0.1:$port,mpm=tcp://127.0.0.1:$((port + 1))"
  rm -rf "$work/tcp"
  "$coupler" run "$scene" --out "$work/tcp" --processes --endpoints "$endpoints" 2> "$work/tcp.log" \
    || fail "tcp run: $(tail -1 "$work/tcp.log")"
fi
[ "$(status_of "$work/tcp")" = completed ] || fail "tcp run: summary not completed"
# Same messages whatever the transport: the audits agree to the last digit.
[ "$(grep -A3 '"mass"' "$work/ipc/summary.json" | grep current)" = \
  "$(grep -A3 '"mass"' "$work/tcp/summary.json" | grep current)" ] || fail "ipc and tcp runs differ"

# 3. a scene the coupler cannot drive is refused before anything is written
if "$coupler" run "$source_dir/configs/sod.yaml" --out "$work/bad" 2> "$work/bad.log"; then
  fail "non-cfdmp scene accepted"
fi
grep -q "needs solver.method cfdmp" "$work/bad.log" || fail "bad scene: $(cat "$work/bad.log")"
[ ! -e "$work/bad" ] || fail "bad scene: output folder created"

# 4. external solvers that never come: named within the timeout
start=$(date +%s)
if "$coupler" run "$scene" --out "$work/absent" --timeout 1 \
     --endpoints "fdm=tcp://127.0.0.1:$((port + 2)),mpm=tcp://127.0.0.1:$((port + 3))" 2> "$work/absent.log"; then
  fail "run without solvers succeeded"
fi
grep -q "solver 'fdm'.*did not answer within 1.0 s" "$work/absent.log" || fail "absent: $(tail -1 "$work/absent.log")"
[ $(( $(date +%s) - start )) -le 10 ] || fail "absent: took more than 10 s"

# 5. external solvers, started by hand, each connecting to its own endpoint
fdm_solver=$(dirname "$coupler")/../fdm_solver/fdm_solver
mpm_solver=$(dirname "$coupler")/../mpm_solver/mpm_solver
ext="fdm=tcp://127.0.0.1:$((port + 4)),mpm=tcp://127.0.0.1:$((port + 5))"
"$coupler" run "$scene" --out "$work/external" --endpoints "$ext" 2> "$work/external.log" &
coupler_pid=$!
"$fdm_solver" serve --endpoint "tcp://127.0.0.1:$((port + 4))" 2> "$work/external_fdm.log" &
fdm_pid=$!
"$mpm_solver" serve --endpoint "tcp://127.0.0.1:$((port + 5))" 2> "$work/external_mpm.log" &
mpm_pid=$!
wait "$coupler_pid" || fail "external run: $(tail -1 "$work/external.log")"
wait "$fdm_pid" || fail "external fdm_solver: $(tail -1 "$work/external_fdm.log")"
wait "$mpm_pid" || fail "external mpm_solver: $(tail -1 "$work/external_mpm.log")"
[ "$(status_of "$work/external")" = completed ] || fail "external run: summary not completed"

# 6. the MPM process killed mid-run: named, the FDM shut down, outputs kept, exit 1
long=$work/long.yaml
sed 's/end: 0.2,/end: 50.0,/' "$scene" > "$long"
"$coupler" run "$long" --out "$work/kill" --processes --timeout 2 2> "$work/kill.log" &
coupler_pid=$!
mpm_pid=""
for _ in $(seq 100); do
  mpm_pid=$(grep -o "solver 'mpm': .* pid [0-9]*" "$work/kill.log" | grep -o '[0-9]*$')
  [ -n "$mpm_pid" ] && [ -e "$work/kill/mpm/snapshots/snapshot_000001.h5" ] && break
  sleep 0.1
done
[ -n "$mpm_pid" ] || { kill "$coupler_pid"; fail "kill: no mpm pid in the log"; }
kill -9 "$mpm_pid"
wait "$coupler_pid" && fail "kill: coupler exited 0"
grep -q "solver 'mpm'.*killed by signal 9" "$work/kill.log" || fail "kill: $(tail -1 "$work/kill.log")"
[ "$(status_of "$work/kill")" = failed ] || fail "kill: summary not failed"
[ -e "$work/kill/fdm/snapshots/snapshot_000001.h5" ] || fail "kill: FDM output lost"
grep -q "shut down" "$work/kill/fdm_solver.log" || fail "kill: FDM not shut down: $(tail -1 "$work/kill/fdm_solver.log")"
# 7. a dormant FSI zone (activation_pressure 0.2 Pa: the shock wakes it) over ipc: the
#    mpm_solver process wakes once, at the switch time, and the recording replays
sed 's/upper: \[1, 0.01, 0.01\]}$/upper: [1, 0.01, 0.01], activation_pressure: 0.2}/' "$scene" \
  > "$work/dormant.yaml"
grep -q "activation_pressure: 0.2" "$work/dormant.yaml" || fail "dormant: scene not edited"
"$coupler" run "$work/dormant.yaml" --out "$work/dormant" --processes --record "$work/dormant.mpfdrec" \
  2> "$work/dormant.log" || fail "dormant run: $(tail -1 "$work/dormant.log")"
[ "$(status_of "$work/dormant")" = completed ] || fail "dormant run: summary not completed"
[ "$(grep -c "FSI zone activated at t = 0.05" "$work/dormant.log")" = 1 ] \
  || fail "dormant run: no single activation line near 0.057 s"
grep -q '"activated": true' "$work/dormant/summary.json" || fail "dormant run: summary not activated"
for solver in fdm mpm; do
  "$coupler" replay "$work/dormant.mpfdrec" --solver $solver > /dev/null 2>&1 \
    || fail "dormant run: replay of $solver differs"
done
echo "PASS"
