#!/usr/bin/env bash
# The docker/compose.yaml topology as three processes on three "hosts": the
# coupler binds one tcp endpoint per solver, each solver connects to it from
# its own address, and cfdmp_sod_1d runs to the end. As root with working
# `ip netns`: three network namespaces joined by veth pairs (coupler 10.231.1.1
# to fdm 10.231.1.2, coupler 10.231.2.1 to mpm 10.231.2.2), each solver's
# /etc/hosts naming the coupler "coupler", so the commands are compose.yaml's
# but for the paths. Otherwise: the loopback addresses 127.0.0.2 (coupler),
# .3 (fdm, as source address) and .4 (mpm).
# Usage: three_hosts_test.sh COUPLER FDM_SOLVER MPM_SOLVER SOURCE_DIR
set -u
coupler=$1
fdm_solver=$2
mpm_solver=$3
scene=$4/configs/cfdmp_sod_1d.yaml
work=$(mktemp -d)
export OMP_WAIT_POLICY=passive
namespaces=()
pids=()
made_etc_netns=false
cleanup() {
  for pid in "${pids[@]}"; do kill -9 "$pid" 2> /dev/null; done
  for ns in "${namespaces[@]}"; do ip netns del "$ns" 2> /dev/null; rm -rf "/etc/netns/$ns"; done
  if $made_etc_netns; then rmdir /etc/netns 2> /dev/null; fi
  rm -rf "$work"
}
trap cleanup EXIT
trap "exit 1" INT TERM
fail() { echo "FAIL: $*"; exit 1; }

tag=mpfd$$
if [ "$(id -u)" = 0 ] && ip netns add "${tag}c" 2> /dev/null; then
  mode="network namespaces"
  namespaces=("${tag}c" "${tag}f" "${tag}m")
  { ip netns add "${tag}f" && ip netns add "${tag}m"; } || fail "ip netns add"
  # One veth pair per solver; interface names stay under 15 characters.
  link() {  # link SOLVER_NS SUBNET: coupler end .1, solver end .2
    ip link add "${tag}c$2" netns "${tag}c" type veth peer name "${tag}s$2" netns "$1" &&
      ip -n "${tag}c" addr add "10.231.$2.1/24" dev "${tag}c$2" &&
      ip -n "$1" addr add "10.231.$2.2/24" dev "${tag}s$2" &&
      ip -n "${tag}c" link set "${tag}c$2" up && ip -n "$1" link set "${tag}s$2" up
  }
  { link "${tag}f" 1 && link "${tag}m" 2; } || fail "veth setup"
  for ns in "${namespaces[@]}"; do ip -n "$ns" link set lo up; done
  on_coupler=(ip netns exec "${tag}c")
  on_fdm=(ip netns exec "${tag}f")
  on_mpm=(ip netns exec "${tag}m")
  # `ip netns exec` mounts /etc/netns/NAME/hosts over /etc/hosts for its command.
  [ -d /etc/netns ] || made_etc_netns=true
  mkdir -p "/etc/netns/${tag}f" "/etc/netns/${tag}m"
  echo "10.231.1.1 coupler" > "/etc/netns/${tag}f/hosts"
  echo "10.231.2.1 coupler" > "/etc/netns/${tag}m/hosts"
  bind="fdm=tcp://0.0.0.0:5555,mpm=tcp://0.0.0.0:5556"
  fdm_connect="tcp://coupler:5555"
  mpm_connect="tcp://coupler:5556"
else
  mode="loopback addresses"
  on_coupler=() on_fdm=() on_mpm=()
  port=$((20000 + $$ % 20000))
  bind="fdm=tcp://127.0.0.2:$port,mpm=tcp://127.0.0.2:$((port + 1))"
  # ZeroMQ's "source;destination" form: each solver connects from its own address.
  fdm_connect="tcp://127.0.0.3:0;127.0.0.2:$port"
  mpm_connect="tcp://127.0.0.4:0;127.0.0.2:$((port + 1))"
fi
echo "three_hosts: $mode"

# Same commands as docker/compose.yaml (addresses aside).
"${on_coupler[@]}" "$coupler" run "$scene" --out "$work/run" --overwrite --endpoints "$bind" --timeout 30 \
  2> "$work/coupler.log" &
coupler_pid=$!
pids+=("$coupler_pid")
"${on_fdm[@]}" "$fdm_solver" serve --endpoint "$fdm_connect" 2> "$work/fdm.log" &
fdm_pid=$!
pids+=("$fdm_pid")
"${on_mpm[@]}" "$mpm_solver" serve --endpoint "$mpm_connect" 2> "$work/mpm.log" &
mpm_pid=$!
pids+=("$mpm_pid")

wait "$coupler_pid" || fail "coupler: $(tail -1 "$work/coupler.log")"
wait "$fdm_pid" || fail "fdm_solver: $(tail -1 "$work/fdm.log")"
wait "$mpm_pid" || fail "mpm_solver: $(tail -1 "$work/mpm.log")"
pids=()
grep -q '"status": *"completed"' "$work/run/summary.json" || fail "summary.json not completed"
ls "$work/run/fdm/snapshots/"*.h5 "$work/run/mpm/snapshots/"*.h5 > /dev/null || fail "no snapshots"
# The same messages as with both solvers in-process: the mass audits agree to the last digit.
"$coupler" run "$scene" --out "$work/inproc" 2> "$work/inproc.log" || fail "in-process run"
[ "$(grep -A3 '"mass"' "$work/run/summary.json" | grep current)" = \
  "$(grep -A3 '"mass"' "$work/inproc/summary.json" | grep current)" ] || fail "tcp and in-process runs differ"
echo "PASS ($mode)"
