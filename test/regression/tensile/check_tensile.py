#!/usr/bin/env python3
"""Checks a tensile_8300 run (examples/tensile_8300) against Foster's law integrated classically under
homogeneous uniaxial stress at the same engineering rate (foster_uniaxial.py, no peridynamics).

usage: check_tensile.py RUN.e|HISTORY.csv [--tol REL] [--from E] [--rate 8300] [--strain 0.25] [--ref-csv OUT]
                        [--history-csv OUT] [--json]
The gauge history (examples/tensile_8300/tensile_history: mean tau_zz against mean Green-Lagrange E_zz of the
middle diameter of the free length) rings about the reference: the yield onset changes the lateral contraction
rate from nu rate to rate/2 within a few tenths of a microsecond, which starts the bar's radial (breathing)
vibration, and nothing damps it (raw amplitude 9 % of the stress at 6 points across, 6.5 % at 10; period
1.39 and 1.54 us, about the first radial mode of a free rod of this radius). The homogeneous reference has no
radial inertia, so the check compares means over one period: the period is measured from the run (mean
spacing of the upward zero crossings of sigma_sim - sigma_ref past E_zz = --from), and both the simulated and
the reference stress (the latter at the simulated E_zz of each frame) are averaged over [t - P/2, t + P/2].
Compared at every frame whose window lies between --from (default 0.01, past the elastic-plastic transition)
and the reference's load maximum (Considere's point, E_zz = 0.0833 at 8300 1/s: past it a neck may grow and the
reference no longer applies; the largest difference to the run's end is printed for information).
Fails (exit 1) if the largest relative difference of the period means exceeds --tol (default 0.015). Its
reason (examples/tensile_8300/README.md, "Verification"): measured -0.46 % (6 across, the ctest deck), -0.38 %
(10 across), -0.37 % (20 across): the lattice's share is below 0.1 %, the rest is the radial ringing's offset
that one-period means leave (largest at E_zz ~ 0.028, where the ringing is); 1.5 % is 3x the coarse deck's.
What it catches (the coarse run against a reference with one constant changed): n 10 % high +2.8 %, Y 2 % high
-2.4 % (both fail); m 10 % high +0.4 % (passes: the rate sensitivity is weak at m = 44).
The measured period must lie within 15 % of the first radial mode of a free elastic cylinder of the bar's
radius (plane strain: x J0(x) = 2 mu/(lambda + 2 mu) J1(x), x = omega R/c_p = 2.165, T = 1.49 us; measured
1.39, 1.54, 1.51 us at 6, 10, 20 across: -7 ... +3 %; 15 % leaves room for the coarse lattice's dispersion),
so that the averaging window is the physical ringing and not noise.
Also fails if the raw ringing exceeds --max-ring (default 0.2 of the stress: measured 0.09; an unstable step
grows without bound), the run did not reach the end strain (the last frame's E_zz short of the reference's
by 10 %), or the gauge never yielded.
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "examples", "tensile_8300"))
import foster_uniaxial  # noqa: E402
from importlib.machinery import SourceFileLoader  # noqa: E402

th = SourceFileLoader("tensile_history", os.path.join(HERE, "..", "..", "..", "examples", "tensile_8300",
                                                      "tensile_history")).load_module()


def radial_mode_period(radius=3.175e-3, rho=2700.0):
    """Period of the first radial (breathing) mode of a free elastic cylinder in plane strain: u_r = J1(k r),
    k = omega/c_p, sigma_rr(R) = 0 gives x J0(x) = 2 mu/(lambda + 2 mu) J1(x), x = k R (scipy's Bessel functions)."""
    from scipy.special import j0, j1
    from scipy.optimize import brentq
    e, nu = foster_uniaxial.E_MOD, foster_uniaxial.NU
    lam, mu = e * nu / ((1 + nu) * (1 - 2 * nu)), e / (2 * (1 + nu))
    cp = ((lam + 2 * mu) / rho) ** 0.5
    x = brentq(lambda v: v * j0(v) - 2 * mu / (lam + 2 * mu) * j1(v), 0.5, 3.5)
    return 2 * np.pi * radius / (x * cp)


def ring_period(t, r):
    """The period of the gauge stress's ringing about the reference: mean spacing of the upward zero
    crossings of r = sigma_sim - sigma_ref (linear interpolation between frames)."""
    up = [t[i] - r[i] * (t[i + 1] - t[i]) / (r[i + 1] - r[i]) for i in range(len(r) - 1) if r[i] < 0.0 <= r[i + 1]]
    if len(up) < 3:
        raise SystemExit("[check_tensile] FAIL: fewer than 3 oscillations of the gauge stress to measure a period")
    return float(np.mean(np.diff(up)))


def window_mean(t, v, width):
    """Mean of the piecewise-linear v(t) over [t_k - width/2, t_k + width/2] at every frame (windows cut at
    the run's ends are shortened)."""
    c = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1]) * np.diff(t))])
    lo = np.clip(t - 0.5 * width, t[0], t[-1])
    hi = np.clip(t + 0.5 * width, t[0], t[-1])
    return (np.interp(hi, t, c) - np.interp(lo, t, c)) / np.maximum(hi - lo, 1e-300)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exodus")
    ap.add_argument("--tol", type=float, default=0.015)
    ap.add_argument("--max-ring", type=float, default=0.2)
    ap.add_argument("--from", dest="e_from", type=float, default=0.01)
    ap.add_argument("--rate", type=float, default=8300.0)
    ap.add_argument("--strain", type=float, default=0.25)
    ap.add_argument("--ref-csv")
    ap.add_argument("--history-csv")
    ap.add_argument("--json", action="store_true")
    a = ap.parse_args()
    t, eg, sig, ep, epr = foster_uniaxial.uniaxial(a.rate, a.strain)
    e_max, _ = foster_uniaxial.considere(t, eg, sig, a.rate)
    if a.ref_csv:
        with open(a.ref_csv, "w") as f:
            f.write("time,E_zz,True_Stress,Equivalent_Plastic_Strain,Equivalent_Plastic_Strain_Rate\n")
            for k in range(0, len(t), 20):
                f.write("%.9g,%.9g,%.9g,%.9g,%.9g\n" % (t[k], eg[k], sig[k], ep[k], epr[k]))
    if a.exodus.endswith(".csv"):  # a stored history (--history-csv of an earlier run: docs/data)
        with open(a.exodus) as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
        info = {"points": 0, "gauge_points": 0}
    else:
        rows, info = th.history(a.exodus)
    if a.history_csv:
        keys = [k for k in ["time", "E_zz", "True_Stress", "True_Stress_Force_Area", "gauge_spread", "free_peak_ratio",
                            "Equivalent_Plastic_Strain", "Equivalent_Plastic_Strain_Rate"] if k in rows[0]]
        with open(a.history_csv, "w") as f:
            f.write(",".join(keys) + "\n")
            for r in rows:
                f.write(",".join("%.9g" % r[k] for k in keys) + "\n")
    fails = []
    tt = np.array([r["time"] for r in rows])
    ee = np.array([r["E_zz"] for r in rows])
    ss = np.array([r["True_Stress"] for r in rows])
    ref = np.interp(ee, eg, sig)
    plastic = (ee >= a.e_from)
    period = ring_period(tt[plastic], (ss - ref)[plastic])
    s_avg = window_mean(tt, ss, period)
    r_avg = window_mean(tt, ref, period)
    fa = np.array([r.get("True_Stress_Force_Area", np.nan) for r in rows])
    fa_avg = window_mean(tt, fa, period)
    # frames whose whole window lies in [e_from, Considere] and inside the run
    sel = plastic & (ee <= e_max) & (tt - 0.5 * period >= tt[plastic][0]) & (tt + 0.5 * period <= tt[-1])
    n = int(np.count_nonzero(sel))
    rel = (s_avg - r_avg) / r_avg
    rel_fa = (fa_avg - r_avg) / r_avg
    raw = (ss - ref) / np.where(ref > 0.0, ref, np.inf)
    k = int(np.argmax(np.where(sel, np.abs(rel), -1.0)))
    worst, worst_at = float(rel[k]), float(ee[k])
    worst_fa = float(rel_fa[sel][np.argmax(np.abs(rel_fa[sel]))]) if n else 0.0
    ring = float(np.max(np.abs(raw[sel]))) if n else 0.0
    # information only: the same measure past Considere's point, to the run's end (the affine-grip bar does
    # not neck: see gauge_spread)
    full = plastic & (tt - 0.5 * period >= tt[plastic][0]) & (tt + 0.5 * period <= tt[-1])
    worst_full = float(rel[full][np.argmax(np.abs(rel[full]))]) if np.any(full) else 0.0
    last = rows[-1]
    at_max = min(rows, key=lambda r: abs(r["E_zz"] - e_max))
    result = {"points": info["points"], "gauge_points": info["gauge_points"], "frames_compared": n,
              "ring_period_s": period, "ring_amplitude_raw": ring, "max_rel_diff": worst, "at_E_zz": worst_at,
              "max_rel_diff_force_area": worst_fa,
              "max_rel_diff_to_end": worst_full,
              "considere_E_zz": e_max, "end_E_zz": last["E_zz"], "end_true_stress": last["True_Stress"],
              "end_ref_stress": float(np.interp(last["E_zz"], eg, sig)),
              "end_gauge_spread": last["gauge_spread"], "end_free_peak_ratio": last["free_peak_ratio"],
              "spread_at_considere": at_max["gauge_spread"],
              "eps_p_rate_at_considere": at_max["Equivalent_Plastic_Strain_Rate"]}
    if n < 5:
        fails.append("only %d frames between E_zz %.3f and %.4f" % (n, a.e_from, e_max))
    if abs(worst) > a.tol:
        fails.append("true stress differs from the uniaxial reference by %.4f at E_zz %.4f (bound %.3f)"
                     % (worst, worst_at, a.tol))
    mode = radial_mode_period()
    result["radial_mode_period_s"] = mode
    if abs(period / mode - 1.0) > 0.15:
        fails.append("ringing period %.3g s is not the radial mode's %.3g s within 15 %%" % (period, mode))
    if ring > a.max_ring:
        fails.append("the gauge stress rings by %.3f of the reference (bound %.2f)" % (ring, a.max_ring))
    if last["E_zz"] < 0.9 * eg[-1]:
        fails.append("the run ends at E_zz %.4f, short of %.4f" % (last["E_zz"], eg[-1]))
    if last["Equivalent_Plastic_Strain"] <= 0.0:
        fails.append("no plastic strain in the gauge")
    if a.json:
        print(json.dumps(result))
    else:
        print("[check_tensile] ringing period %.3g s (first radial mode of the free elastic cylinder %.3g s),"
              " raw amplitude %.3f of the reference" % (period, mode, ring))
        print("[check_tensile] %d points (%d in the gauge); %d frames in E_zz [%.3f, %.4f]: max relative difference"
              " of the period means %+.4f at E_zz %.4f (force/area measure %+.4f); end E_zz %.4f, true stress %.1f MPa"
              " (uniaxial reference %.1f), gauge spread %.4f, largest layer strain / gauge mean %.3f; to the end (past"
              " Considere, information) %+.4f"
              % (info["points"], info["gauge_points"], n, a.e_from, e_max, worst, worst_at or 0.0, worst_fa,
                 last["E_zz"], last["True_Stress"] / 1e6, result["end_ref_stress"] / 1e6, last["gauge_spread"],
                 last["free_peak_ratio"], worst_full))
    for f in fails:
        print("[check_tensile] FAIL: " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
