#!/usr/bin/env bash
# V4 far field (issue 6): the 13.05 g TNT sphere against Kingery-Bulmash at
# Z = 0.5 ... 5 m/kg^(1/3):
#   1d_reference  configs/afdmp_free_air_1d_reference.yaml (mpm_solver run: the
#                 1D spherical MPM alone, h = 0.62 mm, to R = 1.3 m)
#   octant_<n>    configs/afdmp_free_air_3d_far.yaml on n^3 cells (coupler run:
#                 1D start to 0.2 m, then the FDM on [0, 1.25]^3 m)
#   mpm_start_<n> the same octant with AFDMP's MPM start (START=mpm or both):
#                 the charge sampled by the octant's own particles
# Usage: bench/afdmp/v4_far.sh OUT_DIR [CELLS ...]   (default 50 80 125, i.e.
#   h = 25, 15.625, 10 mm; measured 3.5 s / 18 s / 97 s on 2 shared cores,
#   0.07 / 0.23 / 0.85 GiB peak RSS with the 1D start, session 10). Env: COUPLER, MPM_SOLVER (default build/...),
#   START (spherical: the scene's, the default; mpm; both),
#   FDM_AV (solver.fdm.artificial_viscosity for the octants; default the
#   scene's, i.e. the solver default 1), FDM_SWITCH_POWER
#   (solver.fdm.viscosity_switch_power, 1...4; default the scene's, i.e. 1),
#   CFL (time.cfl; default the scene's 0.3),
#   SKIP_1D=1 (reuse OUT_DIR/1d_reference).
# Writes OUT_DIR/<run>/ (the run), OUT_DIR/<run>.yaml, OUT_DIR/runs.csv (label,
# run dir, scene, h, wall time, peak RSS of the largest process) and, through
# bench/afdmp/v4_far.py, OUT_DIR/v4_far.csv (per run and gauge against KB) and
# OUT_DIR/v4_far.png. The machine is shared: wall times compare one invocation.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
out="${1:?usage: v4_far.sh OUT_DIR [CELLS ...]}"
shift
cells_list=("$@")
[[ $# -eq 0 ]] && cells_list=(50 80 125)
coupler="${COUPLER:-$root/build/coupler/coupler}"
mpm_solver="${MPM_SOLVER:-$root/build/mpm_solver/mpm_solver}"
export OMP_WAIT_POLICY=passive
mkdir -p "$out"
runs="$out/runs.csv"

timed() {  # log_file command... -> "wall_s,rss_kib" on stdout
  local log="$1"
  shift
  /usr/bin/time -f "%e,%M" -o "$log.time" "$@" > "$log" 2>&1
  cat "$log.time"
}

if [[ "${SKIP_1D:-0}" != 1 || ! -f "$out/1d_reference.row" ]]; then
  cp "$root/configs/afdmp_free_air_1d_reference.yaml" "$out/1d_reference.yaml"
  t=$(timed "$out/1d_reference.log" "$mpm_solver" run "$out/1d_reference.yaml" \
        --out "$out/1d_reference" --overwrite)
  echo "1D reference,$out/1d_reference,$out/1d_reference.yaml,0.0006205,$t" > "$out/1d_reference.row"
fi
echo "label,run_dir,scene,h_m,wall_s,rss_kib" > "$runs"
cat "$out/1d_reference.row" >> "$runs"

starts=(spherical)
case "${START:-spherical}" in
  spherical) ;;
  mpm) starts=(mpm) ;;
  both) starts=(spherical mpm) ;;
  *) echo "v4_far.sh: START must be spherical, mpm or both, got '$START'" >&2; exit 2 ;;
esac
for start in "${starts[@]}"; do
  for cells in "${cells_list[@]}"; do
    name="octant_$cells"
    label_start=""
    [[ $start == mpm ]] && name="mpm_start_$cells" && label_start=" MPM start"  # no comma: a CSV field
    options=(--start "$start")
    [[ -n "${CFL:-}" ]] && options+=(--cfl "$CFL")
    [[ -n "${FDM_AV:-}" ]] && options+=(--fdm-av "$FDM_AV")
    [[ -n "${FDM_SWITCH_POWER:-}" ]] && options+=(--switch-power "$FDM_SWITCH_POWER")
    /usr/bin/python3 "$here/v4_far_scene.py" "$out/$name.yaml" "$cells" "${options[@]}"
    # --timeout: one FDM step of 2e6 cells takes seconds on a loaded machine
    t=$(timed "$out/$name.log" "$coupler" run "$out/$name.yaml" --out "$out/$name" --overwrite \
          --timeout 900)
    h=$(printf "%.6g" "$(echo "1.25 / $cells" | bc -l)")
    echo "h = $(printf '%.4g' "$(echo "1000 * $h" | bc -l)") mm$label_start,$out/$name,$out/$name.yaml,$h,$t" >> "$runs"
  done
done
/usr/bin/python3 "$here/v4_far.py" "$out" "$runs"
