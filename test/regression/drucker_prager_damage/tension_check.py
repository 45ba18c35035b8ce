#!/usr/bin/env python3
"""Checks a tension_bar.xml run (Maximum Principal Stress damage on a uniform tension bar) against the closed form.

The deck prescribes u_x = 1e-5 t x on every point with y, z free, whose exact discrete equilibrium is uniaxial stress:
sigma1 = sigma_xx = E eps, eps = 1e-5 t. Each step must then be one of
  - sigma1 < f_t: no broken bond (Damage 0 at every point) and sigma_xx = E eps at every point within --stress-bound
    (default 1e-3: the hypoelastic rate form differs from E eps by O(eps) <= 1e-4 and ADR stops at a relative residual
    1e-8; the load steps sit 8 % or more from f_t, so 1e-3 cannot move a step across the threshold);
  - sigma1 > f_t (from the first such step on): every bond broken (Damage 1 at every point) and no stress left.
The first step with E eps > f_t is computed here (t = 4 for the deck's numbers), so a break one step early or late
fails. Exit 1 on any miss.

usage: tension_check.py RUN.e [--rate R] [--stress-bound B]
  --rate R          the deck's strain per unit t (default 1e-5: tension_bar*.xml; the Verlet deck: 1 per s)
  --stress-bound B  default 1e-3 (above); the Verlet deck states its own
Every written frame after t = 0 is checked (the ADR decks write t = 1..10).
"""
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
import argparse

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4

E, FT = 27e9, 1e6


def step_table(exo, step):
    out = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "exodus_to_csv"), exo, "--step", str(step),
                          "--vars", "Damage,Unrotated_Cauchy_StressXX,Unrotated_Cauchy_StressYY,Unrotated_Cauchy_StressZZ"],
                         check=True, capture_output=True, text=True).stdout.splitlines()
    t = float(out[0].split("time =")[1].split()[0])
    head = out[1].split(",")
    return t, [dict(zip(head, map(float, line.split(",")))) for line in out[2:]]


def main(exo, rate, bound):
    bad = 0
    broke_at = None
    with netCDF4.Dataset(exo) as d:
        frames = len(d.variables["time_whole"][:])
    for step in range(2, frames + 1):  # step 1 is t = 0
        t, rows = step_table(exo, step)
        s1 = E * rate * t
        dmin = min(r["Damage"] for r in rows)
        dmax = max(r["Damage"] for r in rows)
        dev = max(abs(r["Unrotated_Cauchy_StressXX"] / s1 - 1) for r in rows)
        lat = max(max(abs(r["Unrotated_Cauchy_StressYY"]), abs(r["Unrotated_Cauchy_StressZZ"])) for r in rows) / s1
        expect_broken = s1 > FT
        print(f"t = {t:.6g}: sigma1 = E eps = {s1 / 1e6:.3f} MPa ({'>' if expect_broken else '<'} f_t); Damage "
              f"{dmin:g} .. {dmax:g}; sigma_xx max {100 * dev:.2e} % off E eps, |sigma_yy|, |sigma_zz| <= {100 * lat:.2e} %")
        if expect_broken:
            if broke_at is None:
                broke_at = t
            if dmin != 1.0:
                print(f"FAIL: t = {t:g}: sigma1 > f_t but a point keeps intact bonds (Damage {dmin:g})")
                bad += 1
        else:
            if dmax != 0.0:
                print(f"FAIL: t = {t:g}: sigma1 < f_t but a bond broke (Damage {dmax:g})")
                bad += 1
            if dev > bound or lat > bound:
                print(f"FAIL: t = {t:g}: the stress is not the uniaxial E eps within {bound:g}")
                bad += 1
    if broke_at is None:
        print("FAIL: no frame has E eps > f_t")
        return 1
    print(f"bonds break first at t = {broke_at:g} (closed form: the first frame with E eps > f_t, after t = "
          f"{FT / (E * rate):.6g})")
    if bad:
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    ap = argparse.ArgumentParser(usage=__doc__)
    ap.add_argument("exo")
    ap.add_argument("--rate", type=float, default=1e-5)
    ap.add_argument("--stress-bound", type=float, default=1e-3)
    a = ap.parse_args()
    sys.exit(main(a.exo, a.rate, a.stress_bound))
