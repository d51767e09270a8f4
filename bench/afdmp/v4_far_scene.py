"""Writes a variant of configs/afdmp_free_air_3d_far.yaml (V4 far field).
Usage: v4_far_scene.py OUT.yaml CELLS [--start spherical|mpm] [--cfl C] [--fdm-av K]
                       [--switch-power P]
  CELLS     cells per axis of the [0, 1.25]^3 m octant (h = 1.25 m / CELLS)
  --start   spherical (the scene's: 1D spherical MPM to 0.2 m, then the FDM) or
            mpm (AFDMP phase 1 on the octant's own grid, as configs/afdmp_free_air_3d.yaml:
            one air particle per cell, 8 per charge cell, uGIMP MUSL, p_ref ambient): the
            charge is then sampled by the 3D grid's particles, so its mass depends on h
  --cfl     time.cfl (default the scene's 0.3); --fdm-av solver.fdm.artificial_viscosity;
  --switch-power solver.fdm.viscosity_switch_power (1...4)"""
import argparse
import os
import re

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCENE = os.path.join(ROOT, "configs", "afdmp_free_air_3d_far.yaml")

MPM_AIR_BODY = """bodies:
  - name: air   # the MPM's air in phase 1, one particle per cell
    material: air
    density: 1.225
    specific_internal_energy: 2.0685e5
    particles_per_axis: 1
    shape: {box: {lower: [0, 0, 0], upper: [1.25, 1.25, 1.25]}}
"""
MPM_SOLVER = """solver:
  method: afdmp
  afdmp: {start: mpm}
  mpm: {shape_function: gimp, update: musl, reference_pressure: 101356.5}
"""


def replace_once(text, old, new):
    if text.count(old) != 1:
        raise SystemExit(f"{SCENE}: expected one '{old.strip()}' to replace")
    return text.replace(old, new)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out")
    parser.add_argument("cells", type=int)
    parser.add_argument("--start", choices=["spherical", "mpm"], default="spherical")
    parser.add_argument("--cfl", type=float)
    parser.add_argument("--fdm-av", type=float)
    parser.add_argument("--switch-power", type=int, choices=[1, 2, 3, 4])
    args = parser.parse_args()
    if args.cells < 2:
        raise SystemExit(f"v4_far_scene.py: CELLS must be >= 2, got {args.cells}")
    text = open(SCENE).read()
    n = args.cells
    text = replace_once(text, "cells: [125, 125, 125]", f"cells: [{n}, {n}, {n}]")
    if args.cfl is not None:
        text = replace_once(text, "cfl: 0.3}", f"cfl: {args.cfl}}}")
    if args.start == "mpm":
        text = replace_once(text, "    burn: program\n",
                            "    burn: program\n    particles_per_axis: 2   # 8 per cell\n")
        text = replace_once(text, "charges:\n", MPM_AIR_BODY + "charges:\n")
        text = text[:text.index("solver:\n")] + MPM_SOLVER
    fdm = []
    if args.fdm_av is not None:
        fdm.append(f"artificial_viscosity: {args.fdm_av}")
    if args.switch_power is not None:
        fdm.append(f"viscosity_switch_power: {args.switch_power}")
    if fdm:
        text = re.sub(r"(?m)^  method: afdmp$",
                      f"  method: afdmp\n  fdm: {{{', '.join(fdm)}}}", text)
    open(args.out, "w").write(text)


if __name__ == "__main__":
    main()
