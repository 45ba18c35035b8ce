#!/usr/bin/env python3
"""Checks a stored Taylor velocity sweep (docs/data/taylor_sweep_<ACROSS>.csv, written by
examples/taylor_impact/run_velocities and taylor_measure; examples/taylor_impact/README.md).

usage: check_sweep.py SWEEP.csv
Per row: L_f/L0 inside the Wilkins & Guinan (1973) band at its speed, L_f/L0 = h/L0 + (1 - h/L0) exp(-rho V^2/(2 Y))
over h/L0 in [0, 0.2] and Y in [276, 445] MPa (the band of check_taylor.py, its reason there); D_f/D0 at least
sqrt(L0/L_f) (the impact face is at least as wide as the mean section of a uniformly shortened bar); the bar has
left the wall (wall force 0 at the end); KE_end/KE_0 below 0.05 (after the rebound only the elastic energy drives
the bar; measured 0.003-0.032); energy_error, where the column exists, within the issue's 1 %. Across the rows:
L_f/L0 strictly decreasing and D_f/D0 strictly increasing with the speed (the monotonicity the README states).
Exit 1 on any miss.
"""
import csv
import math
import sys

RHO, Y_LO, Y_HI = 2700.0, 276e6, 445e6


def band(v):
    return math.exp(-RHO * v * v / (2 * Y_LO)), 0.2 + 0.8 * math.exp(-RHO * v * v / (2 * Y_HI))


def main(path):
    with open(path) as f:
        rows = sorted(({k: float(x) for k, x in r.items() if x != ""} for r in csv.DictReader(f)),
                      key=lambda r: r["speed"])
    fails = []
    for r in rows:
        v, lf, df = r["speed"], r["L_f/L0"], r["D_f/D0"]
        lo, hi = band(v)
        if not lo <= lf <= hi:
            fails.append("%g m/s: L_f/L0 %.4f outside [%.3f, %.3f]" % (v, lf, lo, hi))
        if df < math.sqrt(1.0 / lf):
            fails.append("%g m/s: D_f/D0 %.4f below sqrt(L0/L_f) %.4f" % (v, df, math.sqrt(1.0 / lf)))
        if r["wall_force_at_end"] != 0.0:
            fails.append("%g m/s: the bar still touches the wall at the end" % v)
        if r["KE_end/KE_0"] >= 0.05:
            fails.append("%g m/s: KE_end/KE_0 %.4f" % (v, r["KE_end/KE_0"]))
        if "energy_error" in r and r["energy_error"] > 0.01:
            fails.append("%g m/s: energy_error %.3g above 1 %%" % (v, r["energy_error"]))
        print("[check_sweep] %5g m/s  L_f/L0 %.4f in [%.3f, %.3f]  D_f/D0 %.4f" % (v, lf, lo, hi, df))
    for a, b in zip(rows, rows[1:]):
        if not (b["L_f/L0"] < a["L_f/L0"] and b["D_f/D0"] > a["D_f/D0"]):
            fails.append("not monotonic between %g and %g m/s" % (a["speed"], b["speed"]))
    for f in fails:
        print("[check_sweep] FAIL: " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
