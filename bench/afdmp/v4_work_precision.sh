#!/usr/bin/env bash
# V4 work-precision (issue 6): peak incident overpressure error against
# Kingery-Bulmash (mean |error| over the gauges with Z >= 1) against wall time,
# at three resolutions, for
#   sphere_1d   configs/afdmp_free_air_3d_1d.yaml (start: spherical, the 1D start)
#   sphere_mpm  the same sphere with start: mpm (3D MPM detonation: like for like)
#   cube_mpm    configs/afdmp_free_air_3d.yaml (the thesis's 20 mm cube, start: mpm)
# Usage: bench/afdmp/v4_work_precision.sh OUT_DIR [CELLS ...]   (default 25 50 100,
#   i.e. h = 10, 5, 2.5 mm on the 0.25 m octant: h divides the cube's 10 mm half
#   side; on 80^3 the MPM start's cube holds 10.75 g, not 13.04). Env: COUPLER (default
#   build/coupler/coupler), CASES (default "sphere_1d sphere_mpm cube_mpm"),
#   END (default: the scene's, 3.4e-4 s; KB's arrival at the farthest gauge, R = 0.38 m, is 308 us).
# Writes OUT_DIR/<case>_<cells>/ (the run), OUT_DIR/<case>_<cells>.csv (per gauge,
# bench/afdmp/v4_analyze.py), OUT_DIR/v4_runs.csv (case, cells, h, wall time),
# then bench/afdmp/v4_work_precision.py writes OUT_DIR/v4_work_precision.{csv,png}.
# The machine is shared: the wall times compare runs of one invocation only.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="${1:?usage: v4_work_precision.sh OUT_DIR [CELLS ...]}"
shift
cells_list=("$@")
[[ $# -eq 0 ]] && cells_list=(25 50 100)
coupler="${COUPLER:-$root/build/coupler/coupler}"
cases="${CASES:-sphere_1d sphere_mpm cube_mpm}"
end="${END:-3.4e-4}"  # s
export OMP_WAIT_POLICY=passive
mkdir -p "$out"
runs="$out/v4_runs.csv"
[[ -f "$runs" ]] || echo "case,cells,h_m,wall_s,charge_mass_kg" > "$runs"

scene_of() {  # case cells -> scene text on stdout
  local base start=""
  case "$1" in
    sphere_1d) base=afdmp_free_air_3d_1d.yaml ;;
    sphere_mpm) base=afdmp_free_air_3d_1d.yaml
      start='s/^    start: spherical$/    start: mpm/' ;;
    cube_mpm) base=afdmp_free_air_3d.yaml ;;
    *) echo "unknown case $1" >&2; exit 1 ;;
  esac
  sed -e "s/cells: \[100, 100, 100\]/cells: [$2, $2, $2]/" -e "s/end: [0-9.e+-]*,/end: $end,/" \
      -e "${start:-s/^\$//}" "$root/configs/$base"
}

for cells in "${cells_list[@]}"; do
  for c in $cases; do
    name="${c}_${cells}"
    scene_of "$c" "$cells" > "$out/$name.yaml"
    if [[ "$c" == sphere_mpm ]] && ! grep -q '^    start: mpm$' "$out/$name.yaml"; then
      echo "sphere_mpm: start not switched" >&2; exit 1
    fi
    t0=$(date +%s.%N)
    "$coupler" run "$out/$name.yaml" --out "$out/$name" --overwrite > "$out/$name.log" 2>&1
    t1=$(date +%s.%N)
    wall=$(echo "$t1 - $t0" | bc -l)
    h=$(echo "0.25 / $cells" | bc -l)
    mass=$(/usr/bin/python3 -c "import sys; sys.path.insert(0, '$here'); import v4_analyze as a; print(a.charge_mass_of_run('$out/$name', '$out/$name.yaml'))")
    echo "$c,$cells,$h,$wall,$mass" >> "$runs"
    # KB for the TNT the run holds (v4_analyze.py: auto)
    /usr/bin/python3 "$here/v4_analyze.py" "$out/$name" "$out/$name.yaml" auto > "$out/$name.csv"
    echo "$name: ${wall} s"
  done
done
/usr/bin/python3 "$here/v4_work_precision.py" "$out"
