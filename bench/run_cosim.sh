#!/usr/bin/env bash
# Runs the transport benchmark and prints medians against the targets.
# Usage: bench/run_cosim.sh [build-dir] [output.json]
set -euo pipefail
build_dir=${1:-build}
out=${2:-${build_dir}/cosim_hub_bench.json}
"${build_dir}/bench/cosim/cosim_hub_bench" \
  --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_format=json --benchmark_out="${out}" --benchmark_out_format=json >/dev/null
python3 - "${out}" <<'PY'
import json, re, sys
rows = {b["run_name"]: b for b in json.load(open(sys.argv[1]))["benchmarks"]
        if b.get("aggregate_name") == "median"}
def find(pattern):
    return next(b for name, b in rows.items() if re.fullmatch(pattern, name))
def us(b): return b["real_time"] * {"us": 1, "ms": 1e3, "ns": 1e-3}[b["time_unit"]]
print(f"{'case':<38}{'median':>14}{'target':>14}  ok")
for transport, t in (("ipc", 0), ("tcp", 1)):
    base = {}
    for size, label, limit in ((64, "small", 90.0), (80000, "80 kB", 150.0)):
        b = find(rf"BM_HubStep/tcp:{t}/bytes:{size}/record:0/real_time")
        base[size] = us(b)
        print(f"{transport + ' step ' + label:<38}{us(b):>11.1f} us{'<= %g us' % limit:>14}  "
              f"{'yes' if us(b) <= limit else 'NO'}")
    b = find(rf"BM_HubStep/tcp:{t}/bytes:8000000/record:0/real_time")
    gbs = b["bytes_each_way_per_s"] / 1e9
    print(f"{transport + ' step 8 MB (2 solvers, each way)':<38}{gbs:>10.2f} GB/s{'>= 1 GB/s':>14}  "
          f"{'yes' if gbs >= 1.0 else 'NO'}")
    for size, label in ((64, "small"), (80000, "80 kB")):
        b = find(rf"BM_HubStep/tcp:{t}/bytes:{size}/record:1/real_time")
        change = 100.0 * (us(b) / base[size] - 1.0)
        print(f"{transport + ' recording on, ' + label:<38}{change:>+12.1f} %{'< 5 %':>14}  "
              f"{'yes' if change < 5.0 else 'NO'}")
    b = find(rf"BM_ChunkedFieldExport/tcp:{t}/real_time")
    ms = us(b) / 1e3
    print(f"{transport + ' 64 MiB in 4 MiB chunks':<38}{ms:>11.1f} ms{'<= 80 ms':>14}  "
          f"{'yes' if ms <= 80.0 else 'NO'}")
PY
