#!/usr/bin/python3
"""Timed comparison for the lateral geared rotor (Rao 2023 Table 4.1): 15 s from rest with
Dormand-Prince 5(4) at rtol 1e-8 in geardyn (`geardyn rotor`, wall time of the integration as
reported in summary.json) and in scipy's solve_ivp(method="RK45") with the same right-hand side,
the same tolerances (atol = 1e-8 of the response scale L for displacements and of L n w_e for
velocities, as geardyn scales its state) and the same output grid. Also checks that both agree.

Usage: bench/rotor_scipy_compare.py [path/to/geardyn]   (Debian's python3-scipy)
The issue's target: geardyn >= 50x faster.
"""

import json
import math
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import solve_ivp

CLI = sys.argv[1] if len(sys.argv) > 1 else "build/bin/geardyn"

# Table 4.1 (the rotor schema's defaults).
m1, m2, ks1, ks2, km = 0.310, 1.270, 1e6, 1e6, 6e8
zeta_s = zeta_m = 0.01
cs1, cs2 = 2 * zeta_s * math.sqrt(ks1 * m1), 2 * zeta_s * math.sqrt(ks2 * m2)
cm = 2 * zeta_m * math.sqrt(km * m1 * m2 / (m1 + m2))  # eq. 4.9
em, g = 50e-6, 9.81
tex, phx = [40e-6, 25e-6, 35e-6, 20e-6, 10e-6], 0.785
tey, phy = [30e-6, 15e-6, 25e-6, 10e-6, 5e-6], 1.570
ep, php, eg, phg = 200e-6, 1.047, 300e-6, 2.094
wp = 2 * math.pi * 660 / 60
we = 16 * wp
wg = we / 35
L = max(em, ep, eg, m1 * g / ks1, m2 * g / ks2, *tex, *tey)
W = 5 * we


def rhs(t, s):
    """The corrected eqs. 2.30-2.33 (see include/geardyn/system/lateral_rotor.h)."""
    x1, y1, x2, y2, v1, u1, v2, u2 = s
    cp, sp = math.cos(wp * t + php), math.sin(wp * t + php)
    cg, sg = math.cos(wg * t + phg), math.sin(wg * t + phg)
    ex = ey = em
    dex = dey = 0.0
    for i in range(5):
        a = (i + 1) * we * t
        ex += tex[i] * math.sin(a + phx)
        ey += tey[i] * math.sin(a + phy)
        dex += tex[i] * (i + 1) * we * math.cos(a + phx)
        dey += tey[i] * (i + 1) * we * math.cos(a + phy)
    fx1 = m1 * ep * wp * wp * cp + cs1 * ep * wp * sp - ks1 * ep * cp + cm * (ep * wp * sp - eg * wg * sg + dex) + km * (-ep * cp + eg * cg + ex)
    fy1 = -m1 * g - m1 * ep * wp * wp * sp + cs1 * ep * wp * cp + ks1 * ep * sp + cm * (ep * wp * cp + eg * wg * cg + dey) + km * (ep * sp + eg * sg + ey)
    fx2 = m2 * eg * wg * wg * cg + cs2 * eg * wg * sg - ks2 * eg * cg - cm * (ep * wp * sp - eg * wg * sg + dex) - km * (-ep * cp + eg * cg + ex)
    fy2 = -m2 * g + m2 * eg * wg * wg * sg - cs2 * eg * wg * cg - ks2 * eg * sg - cm * (ep * wp * cp + eg * wg * cg + dey) - km * (ep * sp + eg * sg + ey)
    a1 = (fx1 - (cs1 + cm) * v1 + cm * v2 - (ks1 + km) * x1 + km * x2) / m1
    b1 = (fy1 - (cs1 + cm) * u1 + cm * u2 - (ks1 + km) * y1 + km * y2) / m1
    a2 = (fx2 - (cs2 + cm) * v2 + cm * v1 - (ks2 + km) * x2 + km * x1) / m2
    b2 = (fy2 - (cs2 + cm) * u2 + cm * u1 - (ks2 + km) * y2 + km * y1) / m2
    return [v1, u1, v2, u2, a1, b1, a2, b2]


def main():
    with tempfile.TemporaryDirectory() as folder:
        config = pathlib.Path(folder) / "rotor.toml"
        config.write_text("[output]\nplots = false\n")
        subprocess.run([CLI, "rotor", str(config), "--out", folder, "--quiet"], check=True)
        summary = json.loads((pathlib.Path(folder) / "summary.json").read_text())
        td = summary["results"]["time_domain"]
        rows = np.loadtxt(pathlib.Path(folder) / "time_history.csv", delimiter=",", skiprows=1)
    grid = rows[:, 0]
    atol = np.array([1e-8 * L] * 4 + [1e-8 * L * W] * 4)
    start = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, grid[-1]), np.zeros(8), method="RK45", rtol=1e-8, atol=atol, t_eval=grid)
    scipy_seconds = time.perf_counter() - start
    steady = rows[:, 5] == 1
    difference = np.max(np.abs(sol.y[:4, steady].T - rows[steady, 1:5])) / np.max(np.abs(rows[steady, 1:5]))
    print(f"geardyn Dormand-Prince: {td['wall_time_s']:.3f} s, {td['steps']} steps, {td['rhs_evaluations']} evaluations")
    print(f"scipy solve_ivp RK45:   {scipy_seconds:.3f} s, {sol.nfev} evaluations, status {sol.status}")
    print(f"speed-up: {scipy_seconds / td['wall_time_s']:.1f}x (target >= 50x)")
    print(f"max difference over the steady window: {difference:.2e} of the response")


if __name__ == "__main__":
    main()
