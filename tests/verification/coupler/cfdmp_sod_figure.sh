#!/usr/bin/env bash
# Figure of the CFDMP Sod case (configs/cfdmp_sod_1d.yaml) at t = 0.2 s: density of
# the coupled run (FDM cells left of the zone face, MPM particles right of it),
# pure FDM, pure MPM and the exact solution, as one SVG (plain Python). ~2 s.
# Usage: tests/verification/coupler/cfdmp_sod_figure.sh [build-dir] [out.svg]
set -euo pipefail
build_dir=${1:-build}
svg=${2:-docs/figures/cfdmp_sod.svg}
test="${build_dir}/tests/verification/coupler/coupler_verification"
[[ -x ${test} ]] || { echo "cfdmp_sod_figure.sh: ${test} not built" >&2; exit 1; }
OMP_WAIT_POLICY=passive "${test}" --gtest_filter='*accuracy*' >/dev/null 2>&1
csv=$(/usr/bin/python3 -c 'import tempfile; print(tempfile.gettempdir())')/mpfd-cfdmp-sod-profiles.csv
mkdir -p "$(dirname "${svg}")"
/usr/bin/python3 - "${csv}" "${svg}" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
series = {}
for r in rows:
    series.setdefault(r["series"], []).append((float(r["x"]), float(r["density"])))
W, H, L, B = 760, 440, 60, 50
x0, x1, r0, r1 = 0.3, 1.0, 0.0, 1.1
X = lambda x: L + (W - L - 20) * (x - x0) / (x1 - x0)
Y = lambda r: H - B - (H - B - 30) * (r - r0) / (r1 - r0)
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
for r in (0, 0.2, 0.4, 0.6, 0.8, 1.0):
    out.append(f'<line x1="{L}" y1="{Y(r)}" x2="{W-20}" y2="{Y(r)}" stroke="#ddd"/>')
    out.append(f'<text x="{L-8}" y="{Y(r)+4}" text-anchor="end">{r:.1f}</text>')
for i in range(3, 11):
    x = i / 10
    out.append(f'<text x="{X(x)}" y="{H-B+16}" text-anchor="middle">{x:.1f}</text>')
out.append(f'<rect x="{X(0.6)}" y="30" width="{X(0.65)-X(0.6)}" height="{H-B-30}" fill="#f3e6c8"/>')
out.append(f'<line x1="{X(0.6)}" y1="30" x2="{X(0.6)}" y2="{H-B}" stroke="#b08020" stroke-dasharray="4 3"/>')
out.append(f'<text x="{X(0.6)+4}" y="44">MPM zone face (handshake to 0.65)</text>')
out.append(f'<text x="{(L+W)/2}" y="{H-12}" text-anchor="middle">x [m]</text>')
out.append(f'<text x="16" y="{H/2}" transform="rotate(-90 16 {H/2})" text-anchor="middle">density [kg/m^3]</text>')
pts = " ".join(f"{X(x):.1f},{Y(r):.1f}" for x, r in series["exact"] if x >= x0)
out.append(f'<polyline fill="none" stroke="black" stroke-width="1.2" points="{pts}"/>')
style = {"pure_fdm": ("#999999", 2.0, "none"), "pure_mpm": ("#bbbbbb", 1.2, "none"),
         "cfdmp_fdm": ("#d95f02", 2.6, "#d95f02"), "cfdmp_mpm": ("#1b9e77", 1.4, "#1b9e77")}
for name, (colour, radius, fill) in style.items():
    for x, r in series.get(name, []):
        if x >= x0:
            out.append(f'<circle cx="{X(x):.1f}" cy="{Y(r):.1f}" r="{radius}" fill="{fill}" stroke="{colour}" stroke-width="0.8"/>')
out.append(f'<text x="{L+10}" y="20">Sod, t = 0.2 s, 100 cells: black exact; orange CFDMP FDM cells, green CFDMP MPM '
           'particles; grey open: pure FDM (large), pure MPM (small)</text>')
out.append("</svg>")
open(sys.argv[2], "w").write("\n".join(out))
print("wrote", sys.argv[2])
PY
