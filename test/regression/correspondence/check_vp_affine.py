#!/usr/bin/env python3
"""Checks vp_affine_{verlet,adr}.xml: a Viscoplastic Correspondence cube with every point prescribed in uniaxial
strain u_x = rate x t (rate 1e3 1/s), so every point, the corner too, has F = diag(1 + rate t, 1, 1) exactly.

Reference, independent of the C++ code: a classical radial return of Foster et al. (2010)'s law in principal
values (von Mises q = q_tr - 3 mu dep, q = Y (1 + ep_n/eps0)^(1/n) (1 + dep/(dt rate0))^(1/m), bisection to
1e-15), with each step's strain increment (l_n+1 - l_n)/((l_n+1 + l_n)/2) and dt the difference of consecutive
output times. The model's dt comes from the solver's time only (docs/extending.md, "Time"), so any error in how
the time reaches the material (a wrong or zero dt, a stale committed time) changes the rate term and the flow
stress by percents. Bound: 1e-8 relative at every output step (the two solve the same discrete equations;
measured 1.0e-11 (Verlet) and 5.6e-12 (ADR): round-off and the CSV's 17 digits). The corner's von Mises stress and plastic strain equal the centre's
to the same bound (F exact at a one-sided family).
usage: check_vp_affine.py CSV
"""
import csv
import math
import sys

E, NU, Y, N, M, EPS0, RATE0, RATE = 68.9e9, 0.333, 276e6, 13.5, 44.0, 1e-3, 1e3, 1e3
MU, K = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))


def main(path):
    rows = list(csv.DictReader(open(path)))
    s, p, ep, rate = [0.0, 0.0, 0.0], 0.0, 0.0, 0.0
    worst, ok = 0.0, True
    for prev, row in zip(rows, rows[1:]):
        t0, t1 = float(prev["time"]), float(row["time"])
        dt = t1 - t0
        l0, l1 = 1 + RATE * t0, 1 + RATE * t1
        de = [(l1 - l0) / (0.5 * (l1 + l0)), 0.0, 0.0]
        tr = sum(de)
        s = [s[a] + 2 * MU * (de[a] - tr / 3) for a in range(3)]
        p += K * tr
        q = math.sqrt(1.5 * sum(v * v for v in s))
        g = Y * (1 + ep / EPS0) ** (1 / N)
        rate = 0.0
        if q > g:
            f = lambda d: q - 3 * MU * d - g * (1 + d / (dt * RATE0)) ** (1 / M)
            lo, hi = 0.0, q / (3 * MU)
            while hi - lo > 1e-15 * hi:
                mid = 0.5 * (lo + hi)
                lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
            d = 0.5 * (lo + hi)
            s = [v * (q - 3 * MU * d) / q for v in s]
            ep += d
            rate = d / dt
        vm = math.sqrt(1.5 * sum(v * v for v in s))
        pairs = [("Probe_C_Von_Mises_Stress", vm, Y), ("Probe_C_Unrotated_Cauchy_StressXX", s[0] + p, Y),
                 ("Probe_C_Unrotated_Cauchy_StressYY", s[1] + p, Y), ("Probe_C_Equivalent_Plastic_Strain", ep, 0.05),
                 ("Probe_C_Equivalent_Plastic_Strain_Rate", rate, RATE),
                 ("Probe_Corner_Von_Mises_Stress", vm, Y), ("Probe_Corner_Equivalent_Plastic_Strain", ep, 0.05)]
        for name, ref, scale in pairs:
            err = abs(float(row[name]) - ref) / scale
            worst = max(worst, err)
            if err > 1e-8:
                ok = False
                print(f"t = {t1:.4e}: {name} = {float(row[name]):.10e}, reference {ref:.10e}")
    last = rows[-1]
    print(f"{len(rows) - 1} steps; final von Mises {float(last['Probe_C_Von_Mises_Stress']) / 1e6:.3f} MPa, "
          f"eps_p {float(last['Probe_C_Equivalent_Plastic_Strain']):.5f}, rate "
          f"{float(last['Probe_C_Equivalent_Plastic_Strain_Rate']):.2f} 1/s; largest difference {worst:.2e} (relative)")
    print("check_vp_affine:", "ok" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
