#!/bin/sh
# Converged 1D model reference for V4 (docs/afdmp.md, "Converged 1D model reference
# (Lagrangian)"): every run of that section, one at a time, single-threaded, then the
# tables (OUT_DIR/table_program.md, table_constant_volume.md) and the figure
# (OUT_DIR/v4_lagrangian_reference.png; docs/figures/ holds a copy).
# Usage: bench/afdmp/run_lagrangian_1d.sh [OUT_DIR [--plot-only]]   (default runs/lagrangian_1d)
# About 25 min on one core (the 0.0625 mm run alone is 5-8 min).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-runs/lagrangian_1d}
py=/usr/bin/python3
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$out"
run() { name=$1; shift; echo "== $name"; $py "$here/lagrangian_1d.py" --quiet --out "$out/$name" "$@" | tail -8; }

if [ "${2:-}" != "--plot-only" ]; then
  $py "$here/lagrangian_1d.py" --eos-check > "$out/eos_check.json"
  for dr in 0.006 0.003 0.0015 0.00075; do
    $py "$here/lagrangian_1d.py" --sedov --dr $dr --out "$out/sedov"
  done
  $py "$here/lagrangian_1d.py" --sedov --dr 0.0015 --gamma 1.6666666666666667 --out "$out/sedov"

  for dr in 1e-3 5e-4 2.5e-4 1.25e-4 6.25e-5; do run prog_$dr --dr $dr --start program; done
  for dr in 1e-3 5e-4 2.5e-4 1.25e-4; do run cv_$dr --dr $dr --start constant_volume; done
  run prog_2.5e-4_q2_0.5 --dr 2.5e-4 --cq 2 --cl 0.5
  run prog_1.25e-4_q2_0.5 --dr 1.25e-4 --cq 2 --cl 0.5
  run prog_2.5e-4_q1_0.1 --dr 2.5e-4 --cq 1 --cl 0.1
  run prog_2.5e-4_q4_0.25 --dr 2.5e-4 --cq 4 --cl 0.25
  run prog_2.5e-4_cfl0.25 --dr 2.5e-4 --cfl 0.25
  run prog_2.5e-4_beta --dr 2.5e-4 --beta-burn
  run prog_2.5e-4_charge6.25e-5 --dr 2.5e-4 --dr-charge 6.25e-5
  run prog_5e-4_nomerge --dr 5e-4 --merge-frac 0
fi

prog="$out/prog_1e-3 $out/prog_5e-4 $out/prog_2.5e-4 $out/prog_1.25e-4 $out/prog_6.25e-5"
# shellcheck disable=SC2086
$py "$here/plot_lagrangian_1d.py" $prog --variants "$out"/cv_* "$out"/prog_*_* \
  > "$out/table_program.md"
$py "$here/plot_lagrangian_1d.py" "$out/cv_1e-3" "$out/cv_5e-4" "$out/cv_2.5e-4" "$out/cv_1.25e-4" \
  > "$out/table_constant_volume.md"
# shellcheck disable=SC2086
$py "$here/plot_lagrangian_1d.py" $prog --variants "$out/cv_1.25e-4" "$out/prog_1.25e-4_q2_0.5" \
  --png "$out/v4_lagrangian_reference.png" | tail -1
echo "tables: $out/table_program.md $out/table_constant_volume.md"
