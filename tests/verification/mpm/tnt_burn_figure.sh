#!/usr/bin/env bash
# V2 figure: pressure histories at x = 25, 50, 75 mm of the TNT slab
# (configs/tnt_slab_1d.yaml) with the program burn (T (3-1), (3-2)) and with
# the instantaneous burn ("人工起爆模型": all products at t = 0), drawn as one
# SVG (plain Python, no plotting packages). About 15 s.
# Usage: tests/verification/mpm/tnt_burn_figure.sh [build-dir] [out.svg]
set -euo pipefail
build_dir=${1:-build}
svg=${2:-docs/figures/mpm_tnt_burns.svg}
src=$(cd "$(dirname "$0")/../../.." && pwd)
solver="${build_dir}/mpm_solver/mpm_solver"
[[ -x ${solver} ]] || { echo "tnt_burn_figure.sh: ${solver} not built" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "${work}"' EXIT
sed -e 's/^    detonation_point: .*$//' -e 's/^    burn: program$/    burn: instantaneous/' \
  "${src}/configs/tnt_slab_1d.yaml" >"${work}/instantaneous.yaml"
"${solver}" run "${src}/configs/tnt_slab_1d.yaml" --out "${work}/program" >/dev/null 2>&1
"${solver}" run "${work}/instantaneous.yaml" --out "${work}/instantaneous" >/dev/null 2>&1
mkdir -p "$(dirname "${svg}")"
/usr/bin/python3 - "${work}" "${svg}" <<'PY'
import csv, sys
work, svg = sys.argv[1], sys.argv[2]

def load(run):
    rows = list(csv.reader(open(f"{work}/{run}/gauges.csv")))
    head, data = rows[0], [[float(v) for v in r] for r in rows[1:]]
    t = [r[0] * 1e6 for r in data]
    series = {}
    for g in ("x025", "x050", "x075"):
        i = next(k for k, h in enumerate(head) if h.startswith(g + ".pressure"))
        series[g] = [r[i] / 1e9 for r in data]
    return t, series

W, H, L, B = 720, 420, 60, 50
tmax, pmax = 16.0, 24.0
X = lambda t: L + (W - L - 20) * t / tmax
Y = lambda p: H - B - (H - B - 20) * p / pmax
out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="12">',
       f'<rect width="{W}" height="{H}" fill="white"/>']
for p in range(0, 25, 4):
    out.append(f'<line x1="{L}" y1="{Y(p)}" x2="{W-20}" y2="{Y(p)}" stroke="#ddd"/>')
    out.append(f'<text x="{L-8}" y="{Y(p)+4}" text-anchor="end">{p}</text>')
for t in range(0, 17, 2):
    out.append(f'<text x="{X(t)}" y="{H-B+16}" text-anchor="middle">{t}</text>')
out.append(f'<line x1="{L}" y1="{Y(20.99)}" x2="{W-20}" y2="{Y(20.99)}" stroke="black" stroke-dasharray="4 3"/>')
out.append(f'<text x="{W-24}" y="{Y(20.99)-4}" text-anchor="end">CJ 20.99 GPa</text>')
out.append(f'<text x="{(L+W)/2}" y="{H-12}" text-anchor="middle">time [us]</text>')
out.append(f'<text x="16" y="{H/2}" transform="rotate(-90 16 {H/2})" text-anchor="middle">pressure [GPa]</text>')
colours = {"x025": "#1b9e77", "x050": "#d95f02", "x075": "#7570b3"}
for run, dash in (("program", ""), ("instantaneous", ' stroke-dasharray="6 4"')):
    t, s = load(run)
    for g, c in colours.items():
        pts = " ".join(f"{X(a):.1f},{Y(b):.1f}" for a, b in zip(t, s[g]) if a <= tmax)
        out.append(f'<polyline fill="none" stroke="{c}" stroke-width="1.4"{dash} points="{pts}"/>')
out.append(f'<text x="{L+10}" y="34">TNT slab, GIMP, 1000 cells / 2000 particles: solid = program burn, '
           'dashed = instantaneous; gauges at 25 (green), 50 (orange), 75 mm (purple)</text>')
out.append("</svg>")
open(svg, "w").write("\n".join(out))
print("wrote", svg)
PY
