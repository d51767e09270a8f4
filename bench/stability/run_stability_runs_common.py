"""Shared by the stability-run scripts (quiet_, extreme_, coupling_, random_):
write a scene, run one MPFD program on it under a timeout, and classify the
outcome from its exit status, summary.json and snapshots.

Outcomes:
  bounded      exit 0, summary completed, every snapshot value finite, the
               largest pressure and speed within the stated bounds
  named_error  exit 1 with summary.json status failed and a message (the
               message is recorded)
  refused      exit 1 before the run started (no summary.json), with a message
  unbounded    completed, finite, but beyond the bounds (a silent blow-up)
  nan          a non-finite value in a snapshot or in summary.json
  crash        killed by a signal, or an exit without a failed summary
  hang         still running at the timeout (killed)
"""
import csv
import glob
import json
import os
import signal
import subprocess
import time

import h5py
import numpy as np
import yaml

OUTCOMES = ("bounded", "named_error", "refused", "unbounded", "nan", "crash", "hang")


def program_path(build, name):
    return os.path.join(build, name, name)


class _PlainDumper(yaml.SafeDumper):
    """Writes shared lists in full (no &anchors), as a person would."""

    def ignore_aliases(self, data):
        return True


def write_scene(scene, path):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        yaml.dump(scene, f, Dumper=_PlainDumper, sort_keys=False)


def snapshot_dirs(out):
    """Snapshot folders of a run: the run's own, or fdm/ and mpm/ of a coupler run."""
    dirs = [os.path.join(out, d, "snapshots") for d in ("", "fdm", "mpm")]
    return [d for d in dirs if os.path.isdir(d)]


def snapshot_files(folder):
    return sorted(glob.glob(os.path.join(folder, "snapshot_*.h5")))


def read_snapshot(path):
    """Time, step, every float dataset of one snapshot by its HDF5 path, and the grid's cells."""
    data = {}
    with h5py.File(path, "r") as f:
        t = float(f.attrs["time"])
        step = int(f.attrs["step"])

        def visit(name, obj):
            if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
                data[name] = np.asarray(obj[()])

        f.visititems(visit)
        cells = [int(c) for c in f["grid"].attrs["cells"]]
    return t, step, data, cells


def field_extremes(data):
    """Largest |velocity| and pressure, and whether all values are finite."""
    finite = all(np.all(np.isfinite(v)) for v in data.values())
    speed = 0.0
    pressure = 0.0
    for name, value in data.items():
        if not np.all(np.isfinite(value)):
            continue
        if name.endswith("velocity") and value.size:
            speed = max(speed, float(np.max(np.linalg.norm(value.reshape(-1, 3), axis=1))))
        if name.endswith("pressure") and value.size:
            pressure = max(pressure, float(np.max(value)))
    return finite, speed, pressure


def audit(summary):
    """Relative conservation errors of summary.json, by quantity."""
    out = {}
    for key, value in (summary.get("conservation") or {}).items():
        if isinstance(value, dict) and "relative_error" in value:
            out[key] = value["relative_error"]
    return out


def run_case(program, scene, out, timeout, max_pressure, max_speed, extra_args=()):
    """Runs `program run scene --out out`; returns a dict describing the outcome.

    max_pressure, max_speed: the bounds a bounded run stays within (Pa, m/s)."""
    os.makedirs(out, exist_ok=True)
    scene_file = os.path.join(out, "scene.yaml")
    write_scene(scene, scene_file)
    run_dir = os.path.join(out, "run")
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive")
    args = [program, "run", scene_file, "--out", run_dir, "--overwrite", *extra_args]
    if not program.endswith("coupler"):
        args += ["--threads", "1"]
    start = time.monotonic()
    with open(os.path.join(out, "stderr.log"), "w") as err:
        proc = subprocess.Popen(args, stdout=subprocess.DEVNULL, stderr=err, env=env,
                                start_new_session=True)
        try:
            rc = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            rc = None
    wall = time.monotonic() - start
    result = {"outcome": "", "rc": rc, "wall_s": round(wall, 2), "steps": "", "time_s": "",
              "message": "", "max_speed": "", "max_pressure": "", "audit_mass": "",
              "audit_energy": ""}
    summary = {}
    summary_file = os.path.join(run_dir, "summary.json")
    if os.path.exists(summary_file):
        text = open(summary_file).read()
        try:
            summary = json.loads(text)
        except json.JSONDecodeError:
            summary = {"status": "unreadable"}
        if "NaN" in text or "Infinity" in text:
            summary["non_finite"] = True
    with open(os.path.join(out, "stderr.log")) as f:
        lines = [line.strip() for line in f if line.strip()]
    result["message"] = summary.get("error", lines[-1] if lines else "")
    result["steps"] = summary.get("steps", "")
    result["time_s"] = summary.get("time_s", "")
    errors = audit(summary)
    result["audit_mass"] = errors.get("mass", "")
    result["audit_energy"] = errors.get("energy", "")
    finite = not summary.get("non_finite", False)
    speed = pressure = 0.0
    for folder in snapshot_dirs(run_dir):
        for path in snapshot_files(folder):
            ok, s, p = field_extremes(read_snapshot(path)[2])
            finite = finite and ok
            speed, pressure = max(speed, s), max(pressure, p)
    result["max_speed"] = speed
    result["max_pressure"] = pressure
    if rc is None:
        result["outcome"] = "hang"
    elif rc < 0 or rc > 1:
        result["outcome"] = "crash"
    elif not finite:
        result["outcome"] = "nan"
    elif rc == 1 and not summary and result["message"]:
        result["outcome"] = "refused"
    elif rc == 1:
        named = summary.get("status") == "failed" and bool(summary.get("error"))
        result["outcome"] = "named_error" if named else "crash"
    elif summary.get("status") != "completed":
        result["outcome"] = "crash"
    elif pressure > max_pressure or speed > max_speed:
        result["outcome"] = "unbounded"
    else:
        result["outcome"] = "bounded"
    return result


def write_csv(path, rows):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    keys = []
    for row in rows:
        keys += [k for k in row if k not in keys]
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        for row in rows:
            writer.writerow(row)
