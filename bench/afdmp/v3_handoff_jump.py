#!/usr/bin/env python3
"""The pressure jump at the AFDMP MPM -> FDM handoff in mixed cells, two rules compared.

Usage: v3_handoff_jump.py OLD_RUN NEW_RUN CELLS_PER_AXIS
Both runs: `coupler run` of the same V3 scene (configs/afdmp_blast_2d.yaml re-gridded to
CELLS_PER_AXIS^2 cells) with outputs every step-sized interval around the handoff (e.g.
output.interval 1e-7 to 12 us), so that the FDM's snapshot 0 is taken at the handoff and the
MPM's last snapshot one step before it. OLD_RUN with a coupler or FDM without material_import
(each material of a mixed cell starts from the cell's state), NEW_RUN with it. Prints, per
mixed cell, theta_tnt of both, the particles' volume-weighted pressure and each material's,
and the closure pressure of both; then the largest jumps and the field difference later.
Needs h5py and numpy (/usr/bin/python3). docs/afdmp.md has the figures.
"""
import glob
import sys

import h5py
import numpy as np

PRODUCTS, AIR = 1, 0  # scene material indices of afdmp_blast_2d (air, tnt)


def fdm(run, index):
    f = h5py.File(f"{run}/fdm/snapshots/snapshot_{index:06d}.h5", "r")
    return f["cells/pressure"][0], f["cells/material"][0], f["cells/volume_fraction_tnt"][0]


def last_particles(run):
    f = h5py.File(sorted(glob.glob(f"{run}/mpm/snapshots/*.h5"))[-1], "r")
    return {k: f["particles/" + k][()] for k in ("position", "pressure", "mass", "density",
                                                   "material")}


def main():
    old, new, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
    h = 0.5 / n  # the scene's quarter [0, 0.5]^2 m
    p_old, m_old, t_old = fdm(old, 0)
    p_new, m_new, t_new = fdm(new, 0)
    if not (m_old == m_new).all():
        raise SystemExit("the two runs classify the cells differently at the handoff")
    parts = last_particles(new)
    volume = parts["mass"] / parts["density"]
    ix = np.minimum((parts["position"][:, 0] / h).astype(int), n - 1)
    iy = np.minimum((parts["position"][:, 1] / h).astype(int), n - 1)
    mixed = np.argwhere(m_new == -1)
    print(f"{len(mixed)} mixed cells at the handoff")
    print("cell  theta_tnt old/new  p_particles  p_tnt  p_air  p_old  p_new [MPa]")
    jump_old, jump_new = [], []
    for j, i in mixed:
        sel = (ix == i) & (iy == j)
        mean = np.sum(volume[sel] * parts["pressure"][sel]) / np.sum(volume[sel])
        tnt = np.mean(parts["pressure"][sel & (parts["material"] == PRODUCTS)])
        air = np.mean(parts["pressure"][sel & (parts["material"] == AIR)])
        jump_old.append(abs(p_old[j, i] - mean))
        jump_new.append(abs(p_new[j, i] - mean))
        print(f"({i},{j}) {t_old[j, i]:.3f}/{t_new[j, i]:.3f} {mean / 1e6:9.2f} {tnt / 1e6:9.2f} "
              f"{air / 1e6:7.2f} {p_old[j, i] / 1e6:9.2f} {p_new[j, i] / 1e6:9.2f}")
    print(f"max |p_after - p_particles|: old {max(jump_old) / 1e6:.2f} MPa, new "
          f"{max(jump_new) / 1e6:.2f} MPa")
    print(f"max |p_new - p_old| at the import: {np.max(np.abs(p_new - p_old)) / 1e6:.2f} MPa; "
          f"other cells identical: {np.array_equal(p_new[m_new != -1], p_old[m_new != -1])}")
    for k in (1, 5, 20):
        a, b = fdm(old, k)[0], fdm(new, k)[0]
        print(f"FDM output {k}: max |dp| {np.max(np.abs(a - b)) / 1e6:.3f} MPa in "
              f"{int(np.sum(a != b))} cells")


if __name__ == "__main__":
    main()
