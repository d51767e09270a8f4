#!/usr/bin/python3
"""V6 (T §4.4.2) benchmarks, driven by bench/coupler/run_v6.sh.

(a) CFDMP against pure MPM at one h: wall time, peak RSS, gauge peaks and arrivals.
(b) work-precision: CFDMP gauge peak-overpressure error against a fine pure-FDM
    free-field reference, against wall time, for several h.
(c) coupling overhead share (summary.json timing) over inproc, ipc and tcp.
Scenes are configs/cfdmp_blast_2d.yaml re-gridded: h, the MPM zone's lower
face on the grid line at or above 110 mm, the FDM zone reaching w = 5 cells
past it, gauges at (+-125.1, 250.1) mm (symmetric cells for h = 0.5...4 mm).
Every run goes through /usr/bin/time -v (peak RSS of the whole process tree
is the coupler's for inproc; children are added for ipc/tcp). Results:
<out>/v6_runs.csv, <out>/v6_bench.json; plots by plot_v6.py.
"""
import argparse
import csv
import json
import math
import os
import re
import socket
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
GAUGES = {"p1_fdm": -0.1251, "p2_mpm": 0.1251}


def scene_text(method, h, end, charge="tnt"):
    """configs/cfdmp_blast_2d.yaml at cell size h [m] for method cfdmp, fdm or mpm."""
    text = open(os.path.join(ROOT, "configs", "cfdmp_blast_2d.yaml")).read()
    text = text[text.index("name: "):]
    nx, ny = round(0.34 / h), round(0.5 / h)
    lower = math.ceil(0.11 / h - 1e-9) * h
    fdm_upper = min(lower + 5 * h, 0.16)
    text = re.sub(r"name: \S+", f"name: v6_{method}_h{h * 1e3:g}mm".replace(".", "p"), text, count=1)
    text = re.sub(r"time: \{end: [^,]+,", f"time: {{end: {end!r},", text)
    text = text.replace("0.002]", f"{h!r}]").replace("length: 0.002", f"length: {h!r}")
    text = text.replace("cells: [170, 250, 1]", f"cells: [{nx}, {ny}, 1]")
    text = text.replace("upper: [0.12, 0.5,", f"upper: [{fdm_upper!r}, 0.5,")
    text = text.replace("lower: [0.11, 0,", f"lower: [{lower!r}, 0,")
    text = re.sub(r"gauges:\n(  - .*\n)+",
                  "gauges:\n" + "".join(f"  - {{name: {g}, position: [{x!r}, 0.2501, {h / 2!r}]}}\n"
                                        for g, x in GAUGES.items()), text)
    if charge == "gas":
        text = text.replace("    material: tnt\n", "    material: air\n")
    if method == "fdm":
        text = re.sub(r"zones:\n(  .*\n)+", "", text)
        text = text.replace("method: cfdmp", "method: fdm")
        text = re.sub(r", reference_pressure: [0-9.e+-]+", "", text)  # an MPM option
    if method == "mpm":
        text = re.sub(r"zones:\n(  .*\n)+", "", text)
        text = text.replace("method: cfdmp", "method: mpm")
        # Air over the whole domain: MPM fills no background.
        text = re.sub(r"shape: \{box: \{lower: \[[^\]]*\], upper: \[0.16, 0.5, [^\]]*\]\}\}",
                      f"shape: {{box: {{lower: [-0.18, 0, 0], upper: [0.16, 0.5, {h!r}]}}}}", text)
    return text


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def read_gauges(run_dir):
    rows = list(csv.reader(open(os.path.join(run_dir, "gauges.csv"))))
    header, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
    out = {}
    for g in GAUGES:
        j = header.index(next(c for c in header if c.startswith(g + ".pressure")))
        t = [r[0] for r in data]
        p = [r[j] for r in data]
        p0, peak = p[0], max(p)
        threshold = p0 + 0.1 * (peak - p0)
        k = next((k for k in range(1, len(p)) if p[k] > threshold), None)
        arrival = None if k is None else \
            t[k - 1] + (threshold - p[k - 1]) / (p[k] - p[k - 1]) * (t[k] - t[k - 1])
        out[g] = {"peak_overpressure_Pa": peak - p0, "arrival_s": arrival,
                  "peak_time_s": t[p.index(peak)]}
    return out


def run(args, method, h, transport="inproc", charge=None):
    charge = charge or args.charge
    tag = f"{method}_{transport}_h{h * 1e3:g}mm_{charge}" if method == "cfdmp" else \
        f"{method}_h{h * 1e3:g}mm_{charge}"
    run_dir = os.path.join(args.out, "runs", tag)
    scene = os.path.join(args.out, "scenes", tag + ".yaml")
    os.makedirs(os.path.dirname(scene), exist_ok=True)
    open(scene, "w").write(scene_text(method, h, args.end, charge))
    env = dict(os.environ, OMP_NUM_THREADS=str(args.threads), OMP_WAIT_POLICY="passive")
    children = []
    if method == "cfdmp":
        cmd = [os.path.join(args.build, "coupler", "coupler"), "run", scene, "--out", run_dir,
               "--overwrite", "--timeout", "600"]
        if transport == "ipc":
            cmd.append("--processes")
        elif transport == "tcp":
            ports = {s: free_port() for s in ("fdm", "mpm")}
            urls = {s: f"tcp://127.0.0.1:{p}" for s, p in ports.items()}
            cmd += ["--endpoints", f"fdm={urls['fdm']},mpm={urls['mpm']}"]
    else:
        cmd = [os.path.join(args.build, f"{method}_solver", f"{method}_solver"), "run", scene,
               "--out", run_dir, "--overwrite"]
    timing = os.path.join(args.out, "runs", tag + ".time")
    start = time.monotonic()
    proc = subprocess.Popen(["/usr/bin/time", "-v", "-o", timing] + cmd, env=env,
                            stdout=subprocess.DEVNULL, stderr=open(timing + ".log", "w"))
    if method == "cfdmp" and transport == "tcp":
        time.sleep(1.0)  # the coupler binds first
        for s, url in urls.items():
            prog = os.path.join(args.build, f"{s}_solver", f"{s}_solver")
            children.append(subprocess.Popen(
                ["/usr/bin/time", "-v", "-o", timing + "." + s, prog, "serve", "--endpoint", url],
                env=env, stdout=subprocess.DEVNULL, stderr=open(timing + f".{s}.log", "w")))
    code = proc.wait()
    for c in children:
        c.wait()
    wall = time.monotonic() - start
    rss = 0
    for path in [timing] + [timing + "." + s for s in ("fdm", "mpm") if children]:
        m = re.search(r"Maximum resident set size \(kbytes\): (\d+)", open(path).read())
        rss += int(m.group(1)) * 1024 if m else 0
    if method == "cfdmp" and transport == "ipc":  # children beside the coupler: their logs
        for s in ("fdm", "mpm"):
            log = os.path.join(run_dir, f"{s}_solver.log")
            if os.path.exists(log):
                m = re.findall(r"peak_memory_bytes\D+(\d+)", open(log).read())
                rss += int(m[-1]) if m else 0
    summary_path = os.path.join(run_dir, "summary.json")
    summary = json.load(open(summary_path)) if os.path.exists(summary_path) else {"status": "failed"}
    row = {"tag": tag, "method": method, "transport": transport, "charge": charge,
           "h_mm": h * 1e3, "end_s": args.end, "status": summary.get("status"), "exit": code,
           "wall_s": wall, "peak_rss_bytes": rss, "steps": summary.get("steps")}
    timing_detail = summary.get("details", {}).get("timing", {})
    if "coupling_overhead_share" in timing_detail:
        row.update({"step_s": timing_detail["step_seconds"],
                    "slower_advance_s": timing_detail["slower_advance_seconds"],
                    "coupling_overhead_share": timing_detail["coupling_overhead_share"]})
    if code == 0 and summary.get("status") == "completed":
        for g, v in read_gauges(run_dir).items():
            row[g + "_peak_Pa"] = v["peak_overpressure_Pa"]
            row[g + "_arrival_s"] = v["arrival_s"]
    print(json.dumps(row), flush=True)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--out", required=True)
    parser.add_argument("--parts", default="a,b,c")
    parser.add_argument("--h-a", type=float, default=2.0, help="h of part (a) [mm]")
    parser.add_argument("--h-list", default="4,2,1", help="h of part (b) [mm]")
    parser.add_argument("--h-ref", type=float, default=0.5, help="reference pure-FDM h [mm]")
    parser.add_argument("--h-c", type=float, default=2.0, help="h of part (c) [mm]")
    parser.add_argument("--end", type=float, default=6.0e-5, help="end time [s]")
    parser.add_argument("--charge", choices=["tnt", "gas"], default="tnt")
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    os.makedirs(os.path.join(args.out, "runs"), exist_ok=True)
    results_path = os.path.join(args.out, "v6_runs.csv")
    rows = []
    if os.path.exists(results_path):  # a later part adds to the runs of an earlier call
        rows = list(csv.DictReader(open(results_path)))
    parts = args.parts.split(",")

    def record(key):
        method, h = key[0], key[1] / 1e3
        transport = key[2] if len(key) > 2 else "inproc"
        done = [r for r in rows if r["method"] == method and float(r["h_mm"]) == h * 1e3
                and r.get("transport", "inproc") == transport and r["charge"] == args.charge
                and r["status"] == "completed"]
        if done:  # measured by an earlier call into the same --out
            return
        rows.append(run(args, method, h, transport))
        keys = []
        for r in rows:
            keys += [k for k in r if k not in keys]
        with open(results_path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=keys)
            w.writeheader()
            w.writerows(rows)

    if "a" in parts:
        record(("cfdmp", args.h_a))
        record(("mpm", args.h_a))
    if "b" in parts:
        record(("fdm", args.h_ref))
        for h in [float(x) for x in args.h_list.split(",")]:
            record(("cfdmp", h))
    if "c" in parts:
        for transport in ("inproc", "ipc", "tcp"):
            record(("cfdmp", args.h_c, transport))
    load = os.getloadavg()
    json.dump({"load_average": load, "threads": args.threads, "end_s": args.end, "runs": rows},
              open(os.path.join(args.out, "v6_bench.json"), "w"), indent=1)


if __name__ == "__main__":
    sys.exit(main())
