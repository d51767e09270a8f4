#!/bin/sh
# Converged 1D model reference for V4 (docs/afdmp.md, "Converged 1D model reference
# (Lagrangian)"): every run of that section, one at a time, single-threaded.
# Usage: bench/afdmp/run_lagrangian_1d.sh [OUT_DIR]   (default runs/lagrangian_1d)
# About 20 min on one core (the 0.0625 mm run alone is 5-8 min).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-runs/lagrangian_1d}
py=/usr/bin/python3
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$out"
run() { name=$1; shift; echo "== $name"; $py "$here/lagrangian_1d.py" --quiet --out "$out/$name" "$@" | tail -8; }

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

$py "$here/plot_lagrangian_1d.py" "$out"/prog_1e-3 "$out"/prog_5e-4 "$out"/prog_2.5e-4 \
  "$out"/prog_1.25e-4 "$out"/prog_6.25e-5 --variants "$out"/cv_* "$out"/prog_*_* \
  --png "$out/v4_lagrangian_reference.png"
