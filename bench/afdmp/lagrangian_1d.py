#!/usr/bin/python3
"""Converged 1D spherical reference for V4 (docs/afdmp.md "V4 far field"): a
1D spherical Lagrangian hydrocode, independent of the C++ solvers, run on
exactly the V4 model -- a 13.05 g TNT sphere (r = 12.41 mm, JWL products, no
afterburn) detonated at its centre in ideal-gas air (gamma = 1.4) -- to read the
model's own peak incident overpressure and arrival at Z = 0.5 ... 5 m/kg^(1/3).

Method (SI units throughout):
* von Neumann-Richtmyer staggered grid: node radii r_i and velocities u_i,
  zone-centred mass m_z, density rho_z = m_z / V_z (V_z = 4 pi/3 (r_{z+1}^3 -
  r_z^3)), specific internal energy e_z, pressure p_z, viscosity q_z. Node
  mass M_i = (m_{i-1} + m_i) / 2; node force f_i = 4 pi r_i^2 (P_{i-1} - P_i),
  P = p + q; node 0 (r = 0) stays put; the outer node sees the ambient p0.
* Artificial viscosity, per zone, in compression only (du = u_{z+1} - u_z < 0):
  q = rho (C_QUAD du^2 + C_LIN c |du|), C_QUAD = 2.0, C_LIN = 0.25 (defaults,
  --cq / --cl).
* Time integration: explicit, second order, two-stage (half-step predictor,
  full-step corrector; the time-centred "leapfrog" of compatible Lagrangian
  hydro, Caramana, Burton, Shashkov & Whalen, JCP 146 (1998) 227). The energy
  equation is the compatible one: a zone's internal energy changes by minus
  the work of its own corner forces on the time-centred node velocities,
  m_z de_z = -dt P_z (A_{z+1} ubar_{z+1} - A_z ubar_z), ubar = (u^n + u^{n+1})/2,
  so internal + kinetic + boundary work is conserved to round-off.
* Time step: dt = CFL min_z dr_z / (c_z + 2 (C_QUAD |du_z| + C_LIN c_z)) (the
  second term: the viscous diffusion limit; du only in compression), CFL 0.5,
  growth at most 10 % per step.
* Zones that the wave has not reached are skipped (bit-for-bit unchanged):
  the active region ends 40 zones beyond the last node moving faster than
  1e-9 m/s, whose outer node is held still.
* Air zones that started within --merge-r0 (4) charge radii thin as the shells
  expand (the first to dr/20) and would set dt: once expanded (rho < 1.225) and
  thinner than --merge-frac (0.5) dr, a zone is merged with its thinner air
  neighbour, conserving mass, momentum and total energy (merge_thin; checked
  every 20 steps, 200 zones or more behind the active front).
* The time integration is the two-stage step above rather than a staggered
  one-stage leapfrog: with velocities and positions at the same time level the
  compatible energy update conserves total energy exactly at variable dt.
* TNT: JWL p = A (1 - w/(R1 V)) e^{-R1 V} + B (1 - w/(R2 V)) e^{-R2 V} + w rho e,
  V = rho0/rho, rho0 1630, A 3.712e11, B 3.21e9, R1 4.15, R2 0.95, w 0.3,
  E0 6.993e9 J/m^3 (e0 = E0/rho0 = 4.290 MJ/kg held by every charge zone from
  t = 0). Start "program": program burn from r = 0, D = 6930 m/s, zone
  lighting time t_L = r_zone(t=0) / D (zone-centre radius), p = F p_JWL with
  F = min(1, max(0, (t - t_L) D / (1.5 dr_charge))) (the project's MPM rule,
  mpm_solver/spherical/program_burn.hpp; no volume-burn term unless
  --beta-burn, which takes F = max(F, (1 - V)/(1 - V_CJ)) clipped to [0, 1]).
  Start "constant_volume": F = 1 everywhere at t = 0 (rho0, e0: 8.38 GPa).
* Air: ideal gas gamma 1.4, rho 1.225, e 2.0685e5 J/kg (p0 = 101.36 kPa), to
  r_out = 1.6 m (the shock reaches it after t_end; nothing reflects).
* Gauges at fixed radii R = Z W^(1/3) (W = 13.05 g): every step the pressure p
  (and p + q) is interpolated linearly in r between the two zone centres that
  straddle R. Peak overpressure = max p - p0; arrival = first time p - p0
  exceeds 10 % of the gauge's peak (bench/afdmp/v4_analyze.py's rule; linear
  interpolation between steps); also the first time above p0 + 1 kPa. Every
  zone also keeps its own maximum pressure (Lagrangian peak, the curve of the
  figure).

Usage:
  lagrangian_1d.py --dr 2.5e-4 --start program --out DIR     # V4 model run
  lagrangian_1d.py --sedov --dr 0.003 --out DIR               # Sedov-Taylor check
  lagrangian_1d.py --eos-check                                # JWL hand values, CJ state
A run writes DIR/gauges.csv (per Z: peak, arrival, KB, Henrych), DIR/run.json
(zones, steps, wall time, energy error, ...), DIR/histories.npz (gauge
histories) and DIR/peak_profile.csv (Lagrangian zone peaks against radius).
plot_lagrangian_1d.py reads several run folders (table and figure).
"""
import argparse
import csv
import json
import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import v4_kb  # noqa: E402

FOUR_PI = 4.0 * math.pi

# TNT, T Table 3.1 (configs/afdmp_free_air_1d_reference.yaml)
RHO0_TNT = 1630.0
JWL_A, JWL_B, JWL_R1, JWL_R2, JWL_W = 3.712e11, 3.21e9, 4.15, 0.95, 0.3
E0_TNT = 6.993e9                # J/m^3
e0_TNT = E0_TNT / RHO0_TNT      # J/kg
D_CJ = 6930.0
R_CHARGE = 0.01241
# air
GAMMA_AIR = 1.4
RHO_AIR = 1.225
E_AIR = 2.0685e5
P0 = (GAMMA_AIR - 1.0) * RHO_AIR * E_AIR
W_CHARGE = 4.0 / 3.0 * math.pi * R_CHARGE ** 3 * RHO0_TNT   # 13.05 g
W3 = W_CHARGE ** (1.0 / 3.0)                                # 0.235431
Z_GAUGES = (0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0)


def henrych(z):
    """Henrych (1979) peak incident overpressure [Pa] of a free-air TNT burst."""
    if 1.0 <= z <= 10.0:
        bar = 0.662 / z + 4.05 / z ** 2 + 3.288 / z ** 3
    elif 0.3 <= z < 1.0:
        bar = 6.1938 / z - 0.3262 / z ** 2 + 2.1324 / z ** 3
    elif 0.05 <= z < 0.3:
        bar = 14.0717 / z + 5.5397 / z ** 2 - 0.3572 / z ** 3 + 0.00625 / z ** 4
    else:
        return math.nan
    return 1e5 * bar


# ----------------------------------------------------------------------------- EOS
def jwl_cold(v):
    """Cold terms of JWL and their V-derivative (V = rho0 / rho)."""
    e1, e2 = np.exp(-JWL_R1 * v), np.exp(-JWL_R2 * v)
    pc = JWL_A * (1.0 - JWL_W / (JWL_R1 * v)) * e1 + JWL_B * (1.0 - JWL_W / (JWL_R2 * v)) * e2
    dpc = (JWL_A * e1 * (JWL_W / (JWL_R1 * v * v) - JWL_R1 + JWL_W / v)
           + JWL_B * e2 * (JWL_W / (JWL_R2 * v * v) - JWL_R2 + JWL_W / v))
    return pc, dpc


def jwl(rho, e):
    """JWL pressure and sound speed squared (isentropic)."""
    v = RHO0_TNT / rho
    pc, dpc = jwl_cold(v)
    p = pc + JWL_W * rho * e
    # c^2 = dp/drho|_e + (p / rho^2) dp/de|_rho, dV/drho = -V/rho
    c2 = -dpc * v / rho + JWL_W * e + JWL_W * p / rho
    return p, c2


def jwl_hugoniot(v):
    """Products' Hugoniot from the unreacted state (V = 1, e0): p(V)."""
    pc, _ = jwl_cold(v)
    return (pc + JWL_W * RHO0_TNT / v * e0_TNT) / (1.0 - JWL_W * (1.0 - v) / (2.0 * v))


def eos_check():
    p, c2 = jwl(np.array([RHO0_TNT]), np.array([e0_TNT]))
    v = np.linspace(0.55, 0.95, 400001)
    ph = jwl_hugoniot(v)
    d2 = ph / (RHO0_TNT * (1.0 - v))       # Rayleigh line slope / rho0^2 = D^2
    k = int(np.argmin(d2))
    pcj, vcj = ph[k], v[k]
    rho_cj = RHO0_TNT / vcj
    e_cj = e0_TNT + 0.5 * pcj * (1.0 - vcj) / RHO0_TNT
    _, c2cj = jwl(np.array([rho_cj]), np.array([e_cj]))
    ucj = math.sqrt(d2[k]) * (1.0 - vcj)
    out = {
        "p_constant_volume_Pa": float(p[0]),
        "p_constant_volume_terms_Pa": [
            float(JWL_A * (1 - JWL_W / JWL_R1) * math.exp(-JWL_R1)),
            float(JWL_B * (1 - JWL_W / JWL_R2) * math.exp(-JWL_R2)),
            float(JWL_W * E0_TNT)],
        "c_constant_volume_m_s": float(math.sqrt(c2[0])),
        "e0_J_kg": e0_TNT,
        "cj_from_jwl": {"D_m_s": float(math.sqrt(d2[k])), "p_Pa": float(pcj), "V": float(vcj),
                        "rho_kg_m3": float(rho_cj), "u_m_s": float(ucj),
                        "c_plus_u_over_D": float((math.sqrt(c2cj[0]) + ucj) / math.sqrt(d2[k]))},
        "air_p0_Pa": P0, "charge_mass_kg": W_CHARGE, "W_cube_root": W3,
        "charge_energy_J": E0_TNT * 4.0 / 3.0 * math.pi * R_CHARGE ** 3,
    }
    return out


# ----------------------------------------------------------------------------- hydro
class Lagrangian1D:
    """Spherical Lagrangian hydro; materials: 0 ideal gas, 1 JWL products."""

    def __init__(self, r_nodes, rho, e, material, gamma, cq, cl, cfl, p_ext,
                 lighting_time=None, burn_length=None, burn_start=None, beta_burn=False,
                 active_margin=40):
        self.r = np.asarray(r_nodes, float).copy()
        self.u = np.zeros_like(self.r)
        n = self.r.size - 1
        self.n = n
        vol = FOUR_PI / 3.0 * (self.r[1:] ** 3 - self.r[:-1] ** 3)
        self.m = np.asarray(rho, float) * vol
        self.e = np.asarray(e, float).copy()
        self.mat = np.asarray(material)
        self.gamma = gamma
        self.cq, self.cl, self.cfl = cq, cl, cfl
        self.p_ext = p_ext
        self.M = np.zeros(n + 1)
        self.M[:-1] += 0.5 * self.m
        self.M[1:] += 0.5 * self.m
        self.jwl = np.flatnonzero(self.mat == 1)
        self.gas = np.flatnonzero(self.mat == 0)
        self.jwl_end = int(self.jwl.max()) + 1 if self.jwl.size else 0
        if self.jwl.size:
            assert np.all(self.jwl == np.arange(self.jwl_end)), "JWL zones must come first"
        self.t_light = lighting_time
        self.burn_length = burn_length
        self.burn_F = burn_start  # None: program burn from t_light; array: fixed (constant volume)
        self.beta_burn = beta_burn
        self.v_cj = eos_check()["cj_from_jwl"]["V"] if beta_burn else None
        self.t = 0.0
        self.steps = 0
        self.dt_prev = None
        self.w_ext = 0.0
        self.margin = active_margin
        self.k = n if active_margin is None else min(n, self.jwl_end + active_margin + 1
                                                      if self.jwl_end else active_margin + 1)
        self.rho = self.m / vol
        self.F = np.zeros(self.jwl_end) if burn_start is None else np.asarray(burn_start, float).copy()
        self.p, self.c = self.eos(self.rho, self.e, 0.0, self.n)
        self.q = np.zeros(n)
        self.pmax = self.p.copy()
        self.r0c = 0.5 * (self.r[1:] + self.r[:-1])   # zone centres at t = 0 (mass-weighted on merges)
        self.merges = 0
        self.merge_ke_J = 0.0

    # burn fraction of the JWL zones at time t
    def burn(self, t, rho_jwl):
        if self.burn_F is not None:
            return self.burn_F
        f = np.clip((t - self.t_light) * D_CJ / self.burn_length, 0.0, 1.0)
        if self.beta_burn:
            v = RHO0_TNT / rho_jwl
            f = np.maximum(f, np.clip((1.0 - v) / (1.0 - self.v_cj), 0.0, 1.0))
            f = np.maximum(f, self.F)
        return f

    def eos(self, rho, e, t, k, store_burn=False):
        p = np.empty(k)
        c2 = np.empty(k)
        j = min(self.jwl_end, k)
        if j:
            pj, c2j = jwl(rho[:j], e[:j])
            f = self.burn(t, rho[:j])
            if store_burn:
                self.F = np.asarray(f) * np.ones(j)
            p[:j] = f * pj
            c2[:j] = c2j
        g = (self.gamma - 1.0) * rho[j:] * e[j:]
        p[j:] = g
        c2[j:] = self.gamma * g / rho[j:]
        return p, np.sqrt(np.maximum(c2, 1e-30))

    def viscosity(self, u, rho, c):
        du = np.minimum(u[1:] - u[:-1], 0.0)
        return rho * (self.cq * du * du - self.cl * c * du), -du

    def stable_dt(self):
        k = self.k
        dr = self.r[1:k + 1] - self.r[:k]
        du = -np.minimum(self.u[1:k + 1] - self.u[:k], 0.0)
        c = self.c[:k]
        dt = self.cfl * float(np.min(dr / (c + 2.0 * (self.cq * du + self.cl * c))))
        if self.dt_prev is not None:
            dt = min(dt, 1.1 * self.dt_prev)
        return dt

    def _forces(self, r, P, k):
        a = FOUR_PI * r * r
        f = np.zeros(k + 1)
        f[1:k] = a[1:k] * (P[:-1] - P[1:])
        if k == self.n:
            f[k] = a[k] * (P[k - 1] - self.p_ext)
        return f, a

    def _grow_active(self):
        if self.k == self.n:
            return
        moving = np.flatnonzero(np.abs(self.u[:self.k + 1]) > 1e-9)
        front = int(moving[-1]) if moving.size else 0
        if front > self.k - self.margin:
            self.k = min(self.n, front + 2 * self.margin)

    def step(self, dt):
        self._grow_active()
        k = self.k
        r0, u0, e0 = self.r[:k + 1], self.u[:k + 1], self.e[:k]
        m, M = self.m[:k], self.M[:k + 1]
        fixed_outer = k < self.n
        # stage 1: forces at t^n, half step
        P = self.p[:k] + self.q[:k]
        f, a = self._forces(r0, P, k)
        uh = u0 + 0.5 * dt * f / M
        if fixed_outer:
            uh[k] = 0.0
        ub = 0.5 * (u0 + uh)
        rh = r0 + 0.5 * dt * ub
        au = a * ub
        eh = e0 - 0.5 * dt * P * (au[1:] - au[:-1]) / m
        rhoh = m / (FOUR_PI / 3.0 * (rh[1:] ** 3 - rh[:-1] ** 3))
        ph, ch = self.eos(rhoh, eh, self.t + 0.5 * dt, k)
        qh, _ = self.viscosity(uh, rhoh, ch)
        # stage 2: forces at t^{n+1/2}, full step
        Ph = ph + qh
        fh, ah = self._forces(rh, Ph, k)
        u1 = u0 + dt * fh / M
        if fixed_outer:
            u1[k] = 0.0
        ub = 0.5 * (u0 + u1)
        au = ah * ub
        self.e[:k] = e0 - dt * Ph * (au[1:] - au[:-1]) / m
        if not fixed_outer:
            self.w_ext += dt * self.p_ext * au[k]
        self.r[:k + 1] = r0 + dt * ub
        self.u[:k + 1] = u1
        r1 = self.r[:k + 1]
        vol = FOUR_PI / 3.0 * (r1[1:] ** 3 - r1[:-1] ** 3)
        if np.any(vol <= 0.0):
            raise RuntimeError(f"tangled zone at t = {self.t:.6g} s, step {self.steps}")
        self.rho[:k] = m / vol
        self.t += dt
        self.p[:k], self.c[:k] = self.eos(self.rho[:k], self.e[:k], self.t, k, store_burn=True)
        self.q[:k], _ = self.viscosity(self.u[:k + 1], self.rho[:k], self.c[:k])
        np.maximum(self.pmax[:k], self.p[:k], out=self.pmax[:k])
        self.steps += 1
        self.dt_prev = dt

    def merge_thin(self, dr_ref, frac, r0_max, rho_max, behind):
        """Merges each gas zone thinner than frac dr_ref whose initial centre lies
        below r0_max, whose density is below rho_max (expanded, not shocked) and
        which lies more than `behind` zones inside the active region, with its
        thinner gas neighbour: the node between them goes, its mass and momentum go
        to the two neighbour nodes as the merged zone's half-masses ask, the kinetic
        energy this loses goes into the merged zone's internal energy (total energy
        unchanged). Spherical shells near the products thin as they expand
        (dr ~ (r0/r)^2 rho0/rho: 1/20 of dr0 for the first air zone); they set dt
        but hold no gauge."""
        k = self.k
        if k <= behind + 2:
            return 0
        z_end = k - behind
        dr = self.r[1:z_end + 1] - self.r[:z_end]
        cand = np.flatnonzero((dr < frac * dr_ref) & (self.r0c[:z_end] < r0_max)
                              & (self.rho[:z_end] < rho_max))
        cand = cand[cand >= self.jwl_end]
        done = 0
        last = None   # lowest zone merged so far in this call (candidates run downwards)
        for z in cand[::-1]:
            z = int(z)
            left_ok = z - 1 >= self.jwl_end
            right_ok = z + 1 < z_end
            if not (left_ok or right_ok):
                continue
            if right_ok and (not left_ok or self.r[z + 2] - self.r[z + 1] <= self.r[z] - self.r[z - 1]):
                a = z
            else:
                a = z - 1
            if last is not None and a + 1 >= last:
                continue
            self._merge(a)
            last = a
            done += 1
        if done:
            k = self.k
            self.p[:k], self.c[:k] = self.eos(self.rho[:k], self.e[:k], self.t, k)
            self.q[:k], _ = self.viscosity(self.u[:k + 1], self.rho[:k], self.c[:k])
        return done

    def _merge(self, a):
        """Merges zones a and a + 1 (removes node a + 1)."""
        i = a + 1
        m1, m2 = self.m[a], self.m[a + 1]
        Ml, Mi, Mr = self.M[i - 1], self.M[i], self.M[i + 1]
        ul, ui, ur = self.u[i - 1], self.u[i], self.u[i + 1]
        Ml2, Mr2 = Ml + 0.5 * m2, Mr + 0.5 * m1
        ul2 = (Ml * ul + 0.5 * m2 * ui) / Ml2
        ur2 = (Mr * ur + 0.5 * m1 * ui) / Mr2
        dke = 0.5 * (Ml * ul * ul + Mi * ui * ui + Mr * ur * ur - Ml2 * ul2 * ul2 - Mr2 * ur2 * ur2)
        mm = m1 + m2
        e_new = (m1 * self.e[a] + m2 * self.e[a + 1] + dke) / mm
        self.M[i - 1], self.M[i + 1] = Ml2, Mr2
        self.u[i - 1], self.u[i + 1] = ul2, ur2
        self.r0c[a] = (m1 * self.r0c[a] + m2 * self.r0c[a + 1]) / mm
        self.pmax[a] = max(self.pmax[a], self.pmax[a + 1])
        self.m[a], self.e[a] = mm, e_new
        self.r = np.delete(self.r, i)
        self.u = np.delete(self.u, i)
        self.M = np.delete(self.M, i)
        for name in ("m", "e", "rho", "p", "c", "q", "pmax", "r0c", "mat"):
            setattr(self, name, np.delete(getattr(self, name), a + 1))
        r = self.r
        self.rho[a] = mm / (FOUR_PI / 3.0 * (r[a + 1] ** 3 - r[a] ** 3))
        self.n -= 1
        self.k -= 1
        self.merges += 1
        self.merge_ke_J += dke

    def energies(self):
        ie = float(np.sum(self.m * self.e))
        ke = float(np.sum(0.5 * self.M * self.u * self.u))
        return ie, ke, self.w_ext

    def zone_centres(self, k=None):
        k = self.n if k is None else k
        return 0.5 * (self.r[1:k + 1] + self.r[:k])


class Gauges:
    """Pressure at fixed radii, interpolated between straddling zone centres."""

    def __init__(self, radii, p_ambient):
        self.radii = np.asarray(radii, float)
        self.p_ambient = p_ambient
        self.t, self.p, self.pq = [], [], []

    def sample(self, h):
        k = h.k
        rc = h.zone_centres(k)
        j = np.searchsorted(rc, self.radii)
        p = np.full(self.radii.size, self.p_ambient)
        pq = p.copy()
        inside = (j > 0) & (j < k)
        if np.any(inside):
            jj = j[inside]
            w = (self.radii[inside] - rc[jj - 1]) / (rc[jj] - rc[jj - 1])
            p[inside] = (1 - w) * h.p[jj - 1] + w * h.p[jj]
            pqz = h.p[:k] + h.q[:k]
            pq[inside] = (1 - w) * pqz[jj - 1] + w * pqz[jj]
        self.t.append(h.t)
        self.p.append(p)
        self.pq.append(pq)

    def arrays(self):
        return np.array(self.t), np.array(self.p), np.array(self.pq)


def first_crossing(t, y, level):
    k = np.flatnonzero(y > level)
    if not k.size:
        return math.nan
    i = int(k[0])
    if i == 0:
        return float(t[0])
    return float(t[i - 1] + (level - y[i - 1]) / (y[i] - y[i - 1]) * (t[i] - t[i - 1]))


# ----------------------------------------------------------------------------- V4 run
def v4_setup(args):
    dr_air = args.dr
    dr_c = args.dr_charge or dr_air
    n_c = max(1, int(round(R_CHARGE / dr_c)))
    r_c = np.linspace(0.0, R_CHARGE, n_c + 1)
    n_a = int(round((args.r_out - R_CHARGE) / dr_air))
    r_a = np.linspace(R_CHARGE, args.r_out, n_a + 1)
    r = np.concatenate([r_c, r_a[1:]])
    n = r.size - 1
    mat = np.zeros(n, int)
    mat[:n_c] = 1
    rho = np.where(mat == 1, RHO0_TNT, RHO_AIR)
    e = np.where(mat == 1, e0_TNT, E_AIR)
    centres0 = 0.5 * (r[1:n_c + 1] + r[:n_c])
    burn_length = 1.5 * (R_CHARGE / n_c)
    if args.start == "program":
        kw = dict(lighting_time=centres0 / D_CJ, burn_length=burn_length)
    else:
        kw = dict(burn_start=np.ones(n_c))
    h = Lagrangian1D(r, rho, e, mat, GAMMA_AIR, args.cq, args.cl, args.cfl, P0,
                     beta_burn=args.beta_burn, **kw)
    return h, n_c, n_a


def run_v4(args):
    os.makedirs(args.out, exist_ok=True)
    h, n_c, n_a = v4_setup(args)
    radii = np.array(Z_GAUGES) * W3
    g = Gauges(radii, P0)
    ie0, ke0, w0 = h.energies()
    e_total0 = ie0 + ke0 + w0
    e_charge = E0_TNT * 4.0 / 3.0 * math.pi * R_CHARGE ** 3
    e_err_max = 0.0
    clock = time.process_time()
    wall = time.time()
    g.sample(h)
    interface = [(0.0, R_CHARGE)]
    next_report = 0.0
    while h.t < args.t_end:
        dt = min(h.stable_dt(), args.t_end - h.t)
        h.step(dt)
        g.sample(h)
        if args.merge_frac > 0 and h.steps % 20 == 0 and h.t > R_CHARGE / D_CJ:
            h.merge_thin(args.dr, args.merge_frac, args.merge_r0 * R_CHARGE, RHO_AIR, 200)
        if h.steps % 200 == 0:
            ie, ke, w = h.energies()
            e_err_max = max(e_err_max, abs(ie + ke + w - e_total0))
            interface.append((h.t, float(h.r[n_c])))
        if not args.quiet and h.t >= next_report:
            print(f"t {h.t * 1e3:7.4f} ms  step {h.steps:7d}  dt {dt:.3e}  active {h.k:6d}/{h.n}"
                  f"  wall {time.time() - wall:6.1f} s", flush=True)
            next_report += args.t_end / 10
    cpu = time.process_time() - clock
    wall = time.time() - wall
    ie, ke, w = h.energies()
    e_err = ie + ke + w - e_total0
    e_err_max = max(e_err_max, abs(e_err))
    t, p, pq = g.arrays()
    rows = []
    moving = np.flatnonzero(np.abs(h.u) > 1e-6)
    front_end = float(h.r[moving[-1]]) if moving.size else 0.0
    for i, (z, R) in enumerate(zip(Z_GAUGES, radii)):
        pk = float(np.max(p[:, i]) - P0)
        ipk = int(np.argmax(p[:, i]))
        pqk = float(np.max(pq[:, i]) - P0)
        arr10 = first_crossing(t, p[:, i] - P0, 0.1 * pk)
        arr1k = first_crossing(t, p[:, i] - P0, 1e3)
        lag = float(np.interp(R, h.r0c, h.pmax) - P0)
        kb = v4_kb.overpressure(z)
        kb_arr = v4_kb.arrival_time(W_CHARGE, R)
        hen = henrych(z)
        rows.append({
            "Z": z, "R_m": float(R), "peak_Pa": pk, "peak_time_s": float(t[ipk]),
            "peak_p_plus_q_Pa": pqk, "lagrangian_zone_peak_Pa": lag,
            "arrival_10pct_s": arr10, "arrival_1kPa_s": arr1k,
            "kb_peak_Pa": kb, "peak_vs_kb": pk / kb - 1.0,
            "kb_arrival_s": kb_arr, "arrival_vs_kb": arr10 / kb_arr - 1.0,
            "henrych_peak_Pa": hen, "henrych_vs_kb": hen / kb - 1.0,
            "peak_vs_henrych": pk / hen - 1.0,
            "peak_before_end": bool(t[ipk] < 0.97 * args.t_end),
        })
    with open(os.path.join(args.out, "gauges.csv"), "w", newline="") as fh:
        wr = csv.DictWriter(fh, fieldnames=list(rows[0]))
        wr.writeheader()
        for row in rows:
            wr.writerow({k: (f"{v:.8g}" if isinstance(v, float) else v) for k, v in row.items()})
    # Lagrangian peak profile, air zones, decimated to <= 4000 rows
    air = np.arange(n_c, h.n)
    stride = max(1, air.size // 4000)
    sel = np.concatenate([np.arange(0, n_c), air[::stride]])
    with open(os.path.join(args.out, "peak_profile.csv"), "w") as fh:
        fh.write("r0_m,Z,peak_overpressure_Pa,material\n")
        for j in sel:
            fh.write(f"{h.r0c[j]:.7g},{h.r0c[j] / W3:.7g},{h.pmax[j] - P0:.7g},"
                     f"{'tnt' if j < n_c else 'air'}\n")
    stride = max(1, t.size // 200000)
    np.savez_compressed(os.path.join(args.out, "histories.npz"), t=t[::stride], p=p[::stride],
                        p_plus_q=pq[::stride], radii=radii, Z=np.array(Z_GAUGES),
                        interface=np.array(interface))
    info = {
        "model": "V4: 13.05 g TNT sphere (JWL), ideal-gas air gamma 1.4, 1D spherical Lagrangian",
        "start": args.start, "beta_burn": args.beta_burn,
        "dr_air_m": args.dr, "dr_charge_m": R_CHARGE / n_c, "zones_charge": n_c, "zones_air": n_a,
        "zones": h.n, "r_out_m": args.r_out, "t_end_s": args.t_end, "steps": h.steps,
        "cfl": args.cfl, "c_quad": args.cq, "c_lin": args.cl,
        "wall_s": wall, "cpu_s": cpu,
        "charge_mass_kg": W_CHARGE, "charge_energy_J": e_charge,
        "energy_total_J": e_total0, "energy_error_end_J": e_err,
        "energy_error_max_J": e_err_max,
        "energy_error_rel_charge": e_err_max / e_charge,
        "energy_error_rel_total": e_err_max / e_total0,
        "energy_end_J": {"internal": ie, "kinetic": ke, "boundary_work": w},
        "products_radius_end_m": float(h.r[n_c]),
        "front_radius_end_m": front_end,
        "merges": h.merges, "merge_ke_to_ie_J": h.merge_ke_J,
        "merge": {"frac": args.merge_frac, "r0_max_m": args.merge_r0 * R_CHARGE},
        "active_zones_end": h.k,
    }
    with open(os.path.join(args.out, "run.json"), "w") as fh:
        json.dump(info, fh, indent=1)
    print(json.dumps(info, indent=1))
    for row in rows:
        print(f"Z {row['Z']:4.2f}  peak {row['peak_Pa'] / 1e3:9.2f} kPa  KB {row['kb_peak_Pa'] / 1e3:9.2f}"
              f"  {100 * row['peak_vs_kb']:+6.1f} %  (zone peak {row['lagrangian_zone_peak_Pa'] / 1e3:9.2f},"
              f" p+q {row['peak_p_plus_q_Pa'] / 1e3:9.2f})  arrival {row['arrival_10pct_s'] * 1e3:.4f} ms"
              f" KB {row['kb_arrival_s'] * 1e3:.4f} ({100 * row['arrival_vs_kb']:+.1f} %)")


# ----------------------------------------------------------------------------- Sedov
def sedov_alpha(gamma, nu=3, h=-2e-4):
    """alpha of E = alpha rho0 R^(nu+2) / t^2 by integrating the similarity ODEs
    inwards (the method of tests/verification/support/sedov.cpp, fixed-step RK4
    in s = ln(lambda) with the energy-integral projection of U)."""
    def deriv(s, y):
        lam = math.exp(s)
        u = y[1]
        w = u - lam
        ic2 = math.exp(y[0] - y[2]) / gamma
        du = (0.5 * nu * u * w * ic2 * lam - nu * lam / gamma + (nu - 1) * u) / (w * w * ic2 - 1.0)
        div = du + (nu - 1) * u
        return np.array([-div / w, du, (nu * lam - gamma * div) / w,
                         (0.5 * math.exp(y[0]) * u * u + math.exp(y[2]) / (gamma - 1.0)) * lam ** nu])

    def project(u, s, y):
        lam = math.exp(s)
        kk = 0.5 * (gamma - 1.0) * math.exp(y[0] - y[2])
        for _ in range(30):
            g = gamma * u - lam - kk * (lam - u) * u * u
            dg = gamma - kk * (2.0 * lam * u - 3.0 * u * u)
            d = g / dg
            u -= d
            if abs(d) < 1e-15 * abs(u):
                break
        return u

    y = np.array([math.log((gamma + 1) / (gamma - 1)), 2 / (gamma + 1), math.log(2 / (gamma + 1)), 0.0])
    s = 0.0
    thr = 1e-9 * (gamma - 1) / (2 * gamma)
    while True:
        w = y[1] - math.exp(s)
        if w * w * math.exp(y[0] - y[2]) / gamma < thr or s < -60:
            break
        k1 = deriv(s, y)
        k2 = deriv(s + h / 2, y + h / 2 * k1)
        k3 = deriv(s + h / 2, y + h / 2 * k2)
        k4 = deriv(s + h, y + h * k3)
        y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        s += h
        y[1] = project(y[1], s, y)
    lam = math.exp(s)
    tail = (math.exp(y[2]) * lam ** nu / (nu * (gamma - 1))
            + math.exp(y[0]) * lam ** (nu + 2) / (2 * gamma * gamma * (nu / (gamma - 1) + nu + 2)))
    delta = 2.0 / (nu + 2)
    sigma = {1: 1.0, 2: 2 * math.pi, 3: 4 * math.pi}[nu]
    return sigma * delta * delta * (tail - y[3])


def run_sedov(args):
    os.makedirs(args.out, exist_ok=True)
    gamma = args.gamma
    r_out = 1.2
    n = int(round(r_out / args.dr))
    r = np.linspace(0.0, r_out, n + 1)
    rho0, energy = 1.0, 1.0
    e_amb = 1e-10
    mat = np.zeros(n, int)
    vol0 = FOUR_PI / 3.0 * (r[1] ** 3)
    e = np.full(n, e_amb)
    e[0] = energy / (rho0 * vol0)
    h = Lagrangian1D(r, np.full(n, rho0), e, mat, gamma, args.cq, args.cl, args.cfl, 0.0,
                     active_margin=40)
    alpha = sedov_alpha(gamma)
    xi0 = alpha ** -0.2
    e_total0 = sum(h.energies())
    times = [0.1, 0.25, 0.5, 0.75, 1.0]
    out = []
    wall = time.time()
    for tt in times:
        while h.t < tt:
            h.step(min(h.stable_dt(), tt - h.t))
        rc = h.zone_centres()
        k = int(np.argmax(h.rho))
        rho_pk = float(h.rho[k])
        half = 0.5 * (rho0 + rho_pk)
        # front: outermost crossing of the half-peak density ahead of the peak
        j = k + int(np.flatnonzero(h.rho[k:] < half)[0])
        rs = float(rc[j - 1] + (half - h.rho[j - 1]) / (h.rho[j] - h.rho[j - 1]) * (rc[j] - rc[j - 1]))
        r_exact = xi0 * (energy * tt * tt / rho0) ** 0.2
        out.append({"t": tt, "R_shock": rs, "R_exact": r_exact, "R_error": rs / r_exact - 1.0,
                    "R_peak_zone": float(rc[k]), "rho_peak": rho_pk,
                    "rho_peak_over_strong_shock": rho_pk / ((gamma + 1) / (gamma - 1) * rho0),
                    "p_peak": float(h.p.max()),
                    "zones_across_R": r_exact / args.dr})
    e_err = sum(h.energies()) - e_total0
    info = {"gamma": gamma, "alpha": alpha, "xi0": xi0, "dr": args.dr, "zones": n, "steps": h.steps,
            "c_quad": args.cq, "c_lin": args.cl, "cfl": args.cfl, "wall_s": time.time() - wall,
            "energy_error_rel": e_err / energy, "samples": out}
    with open(os.path.join(args.out, f"sedov_g{gamma:g}_dr{args.dr:g}.json"), "w") as fh:
        json.dump(info, fh, indent=1)
    print(f"Sedov gamma {gamma} alpha {alpha:.6f} xi0 {xi0:.5f} dr {args.dr} zones {n} steps {h.steps}"
          f" wall {info['wall_s']:.1f} s energy error {e_err / energy:.2e}")
    for o in out:
        print(f"  t {o['t']:5.2f}  R {o['R_shock']:.5f} exact {o['R_exact']:.5f} ({100 * o['R_error']:+.2f} %)"
              f"  rho_peak {o['rho_peak']:.4f} ({100 * (o['rho_peak_over_strong_shock'] - 1):+.1f} % vs"
              f" {(gamma + 1) / (gamma - 1):.1f})")
    return info


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--dr", type=float, default=2.5e-4, help="zone width in the air [m] (Sedov: all zones)")
    ap.add_argument("--dr-charge", type=float, default=None, help="zone width in the charge [m] (default: --dr)")
    ap.add_argument("--start", choices=("program", "constant_volume"), default="program")
    ap.add_argument("--beta-burn", action="store_true", help="F = max(program, (1-V)/(1-V_CJ))")
    ap.add_argument("--out", default="runs/lagrangian_1d")
    ap.add_argument("--r-out", type=float, default=1.6)
    ap.add_argument("--t-end", type=float, default=2.6e-3)
    ap.add_argument("--cfl", type=float, default=0.5)
    ap.add_argument("--cq", type=float, default=2.0, help="quadratic viscosity coefficient")
    ap.add_argument("--cl", type=float, default=0.25, help="linear viscosity coefficient")
    ap.add_argument("--merge-frac", type=float, default=0.5,
                    help="merge expanded air zones thinner than this times --dr (0: never)")
    ap.add_argument("--merge-r0", type=float, default=4.0,
                    help="... only those that started within this many charge radii")
    ap.add_argument("--sedov", action="store_true", help="Sedov-Taylor validation instead")
    ap.add_argument("--gamma", type=float, default=1.4, help="Sedov gas gamma")
    ap.add_argument("--eos-check", action="store_true", help="print JWL hand values and exit")
    ap.add_argument("--quiet", action="store_true")
    args = ap.parse_args(argv)
    if args.eos_check:
        print(json.dumps(eos_check(), indent=1))
        return
    if args.sedov:
        run_sedov(args)
        return
    run_v4(args)


if __name__ == "__main__":
    main()
