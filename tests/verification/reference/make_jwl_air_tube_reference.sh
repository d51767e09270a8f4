#!/usr/bin/env bash
# Regenerates jwl_air_tube_40us.csv: configs/jwl_air_tube.yaml run on
# 8000 cells (dx = 62.5 um) to 40 us, averaged onto 1000 cells of 0.5 mm.
# Usage: make_jwl_air_tube_reference.sh <build-dir>
set -euo pipefail
build=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed 's/cells: \[500, 1, 1\]/cells: [8000, 1, 1]/; s/interval: 1.0e-5/interval: 4.0e-5/' \
  "$here/../../../configs/jwl_air_tube.yaml" >"$work/fine.yaml"
"$build/fdm_solver/fdm_solver" run "$work/fine.yaml" --out "$work/out" >/dev/null
/usr/bin/python3 - "$work/out" "$here/jwl_air_tube_40us.csv" <<'PY'
import glob, sys
import h5py, numpy as np
snap = sorted(glob.glob(sys.argv[1] + "/snapshots/*.h5"))[-1]
with h5py.File(snap) as h:
    assert abs(h.attrs["time"] - 4.0e-5) < 1e-12
    rho = h["cells/density"][0, 0, :]
    u = h["cells/velocity"][0, 0, :, 0]
    p = h["cells/pressure"][0, 0, :]
group = 8  # fine cells per reference cell
avg = lambda a: a.reshape(-1, group).mean(axis=1)
x = (np.arange(rho.size // group) + 0.5) * 0.5 / (rho.size // group)
with open(sys.argv[2], "w") as out:
    out.write("# configs/jwl_air_tube.yaml at t = 40 us, 8000 cells averaged onto 1000;\n")
    out.write("# made by make_jwl_air_tube_reference.sh\n")
    out.write("x_m,density_kg_m3,velocity_m_s,pressure_pa\n")
    for row in zip(x, avg(rho), avg(u), avg(p)):
        out.write("%.6e,%.9e,%.9e,%.9e\n" % row)
PY
