#!/usr/bin/env bash
# Runs the transport benchmark (MPFD hub + two solver stubs, and the same step
# on bare ZeroMQ as a baseline, in one run) and prints medians against the
# issue's targets, with MPFD's overhead as a ratio to bare ZeroMQ.
# Usage: bench/run_cosim.sh [build-dir] [output.json]
set -euo pipefail
build_dir=${1:-build}
out=${2:-${build_dir}/cosim_hub_bench.json}
"${build_dir}/bench/cosim/cosim_hub_bench" \
  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_format=json --benchmark_out="${out}" --benchmark_out_format=json >/dev/null
/usr/bin/python3 - "${out}" <<'PY'
import json, re, sys
doc = json.load(open(sys.argv[1]))
rows = {b["run_name"]: b for b in doc["benchmarks"] if b.get("aggregate_name") == "median"}
def find(pattern):
    return next(b for name, b in rows.items() if re.fullmatch(pattern, name))
def us(b): return b["real_time"] * {"us": 1, "ms": 1e3, "ns": 1e-3}[b["time_unit"]]
def bare(t, size): return us(find(rf"BM_BareZmqStep/tcp:{t}/bytes:{size}/real_time"))
print(f"load average at start: {doc['context'].get('load_avg', ['?'])[0]}")
print(f"{'case':<36}{'MPFD':>12}{'bare zmq':>12}{'ratio':>8}{'target':>13}  met")
for transport, t in (("ipc", 0), ("tcp", 1)):
    base = {}
    for size, label, limit in ((64, "small", 90.0), (80000, "80 kB", 150.0)):
        b = us(find(rf"BM_HubStep/tcp:{t}/bytes:{size}/record:0/real_time"))
        base[size] = b
        z = bare(t, size)
        print(f"{transport + ' step ' + label:<36}{b:>9.1f} us{z:>9.1f} us{b / z:>8.2f}"
              f"{'<= %g us' % limit:>13}  {'yes' if b <= limit else 'NO'}")
    b = find(rf"BM_HubStep/tcp:{t}/bytes:8000000/record:0/real_time")
    gbs = b["bytes_each_way_per_s"] / 1e9
    zgbs = 2 * 8e6 / (bare(t, 8000000) * 1e-6) / 1e9
    print(f"{transport + ' step 8 MB, each way':<36}{gbs:>7.2f} GB/s{zgbs:>7.2f} GB/s{zgbs / gbs:>8.2f}"
          f"{'>= 1 GB/s':>13}  {'yes' if gbs >= 1.0 else 'NO'}")
    for size, label in ((64, "small"), (80000, "80 kB")):
        b = find(rf"BM_RecordingOverhead/tcp:{t}/bytes:{size}/iterations:40")
        change = b["change_percent"]
        print(f"{transport + ' recording on, ' + label + ' (paired)':<36}{change:>+10.1f} %"
              f"{'':>20}{'< 5 %':>13}  {'yes' if change < 5.0 else 'NO'}")
    b = find(rf"BM_ChunkedFieldExport/tcp:{t}/real_time")
    ms = us(b) / 1e3
    print(f"{transport + ' 64 MiB in 4 MiB chunks':<36}{ms:>9.1f} ms{'':>20}{'<= 80 ms':>13}  "
          f"{'yes' if ms <= 80.0 else 'NO'}")
PY
