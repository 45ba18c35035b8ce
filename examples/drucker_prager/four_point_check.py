#!/usr/bin/env python3
"""Checks and summarises the four-point bending runs (make_four_point.py).

usage:
  four_point_check.py elastic RUN.e RUN.csv [--curvature-bound R] [--deflection-bound R]
      The unflawed elastic deck against beam theory (plane strain: E' = E / (1 - nu^2); per load point F = P / 2):
      - curvature in the constant-moment zone: eps_xx(y) = (u_x(mid + d, y) - u_x(mid - d, y)) / (2 d), d = 12.5 mm,
        fitted by a line over the rows at least delta from the top and bottom faces; its slope against
        kappa = M / (E' I), M = F a (Euler-Bernoulli; the shear force is zero there, so no shear correction);
      - load-point deflection: v against F a^2 (3 S - 4 a) / (6 E' I) + F a / (kappa_s G A), kappa_s = 5/6
        (Timoshenko's shear correction), from the history's Applied_Displacement and load reactions.
      Exit 1 if the curvature misses by more than --curvature-bound or the deflection by more than
      --deflection-bound (each only when given). The bounds and their reasons are in the ctest file.
  four_point_check.py damage RUN.e RUN.csv [--out CURVE.csv] [--expect-first-crack lower-right]
      The flawed deck with damage: the load-displacement curve (P = -(R_LoadL + R_LoadR), v = -applied; --out writes
      it as a history-style CSV, columns Applied_Displacement = v and Reaction_Total_Y = P, for scripts/plot_history), the peak,
      the first step with a broken bond and where (the damaged points' centroid, relative to the flaws), the first
      step with damage near the upper flaw. --expect-first-crack lower-right: exit 1 unless the first damage lies
      at the right side of the lower flaw (x > its tip's x - delta, y below mid-depth) and before any damage
      near the upper flaw. --expect KEY=VALUE:RELTOL (repeatable): exit 1 unless the measured peak_load [N], peak_v [m],
      stiffness [N/m] (P/v of the first step) or first_damage_t is within RELTOL of VALUE (regression guards on the
      numbers four_point_bending.md reports).
"""
import argparse
import csv
import math
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import make_four_point as g  # noqa: E402

DELTA = 3.015 * g.DX


def table(exo, step, names):
    out = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "exodus_to_csv"), exo, "--step", str(step),
                          "--vars", ",".join(names)], check=True, capture_output=True, text=True).stdout.splitlines()
    t = float(out[0].split("time =")[1].split()[0])
    head = out[1].split(",")
    return t, [dict(zip(head, map(float, line.split(",")))) for line in out[2:]]


def history(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    out = []
    for r in rows:
        v = -float(r["Applied_Displacement"])
        p = -(float(r["Reaction_LoadL_Y"]) + float(r["Reaction_LoadR_Y"]))
        out.append((float(r["time"]), v, p))
    return out


def nsteps(exo):
    import netCDF4
    with netCDF4.Dataset(exo) as d:
        return len(d.variables["time_whole"][:])


def elastic(a):
    Ep = g.E / (1 - g.NU ** 2)
    G = g.E / (2 * (1 + g.NU))
    I = g.B * g.H ** 3 / 12
    A = g.B * g.H
    S = g.SUPPORTS[1] - g.SUPPORTS[0]
    aa = g.LOADS[0] - g.SUPPORTS[0]
    hist = history(a.csv)
    t, rows = table(a.exo, -1, ["DisplacementX", "DisplacementY"])
    P = [p for (tt, v, p) in hist if abs(tt - t) < 1e-9][0]
    v = [v for (tt, v, p) in hist if abs(tt - t) < 1e-9][0]
    F = P / 2
    M = F * aa
    mid, d = g.L / 2, 0.0125
    ux = {}
    for r in rows:
        for side, xc in (("-", mid - d), ("+", mid + d)):
            if abs(r["X"] - xc) < 0.51 * g.DX:  # the grid columns straddling mid +- d (cell centres): average
                ux.setdefault(round(r["Y"], 6), {}).setdefault(side, []).append(r["DisplacementX"])
    pts = []
    for y, s in sorted(ux.items()):
        if y < DELTA or y > g.H - DELTA or "-" not in s or "+" not in s:
            continue
        up, um = sum(s["+"]) / len(s["+"]), sum(s["-"]) / len(s["-"])
        # the columns averaged sit at mid +- d +- dx/2: their mean positions are mid +- d exactly
        pts.append((y - g.H / 2, (up - um) / (2 * d)))
    n = len(pts)
    my = sum(p[0] for p in pts) / n
    me = sum(p[1] for p in pts) / n
    slope = sum((p[0] - my) * (p[1] - me) for p in pts) / sum((p[0] - my) ** 2 for p in pts)
    kappa_pd = -slope  # sagging: eps_xx = -kappa (y - y_na)
    kappa_bt = M / (Ep * I)
    dk = kappa_pd / kappa_bt - 1
    bend = F * aa ** 2 * (3 * S - 4 * aa) / (6 * Ep * I)
    shear = F * aa / (5.0 / 6.0 * G * A)
    dv = v / (bend + shear) - 1
    print(f"{a.exo}: t = {t:g}, applied v = {v * 1e6:.4f} um, total load P = {P:.3f} N (F = {F:.3f} N per point)")
    print(f"  beam: E' = E/(1-nu^2) = {Ep / 1e9:.3f} GPa, I = {I:.4e} m^4, S = {S * 1e3:g} mm, a = {aa * 1e3:g} mm")
    print(f"  curvature in the constant-moment zone ({n} rows at least delta from the faces): PD {kappa_pd:.5e} 1/m, "
          f"Euler-Bernoulli M/(E'I) {kappa_bt:.5e} 1/m: {100 * dk:+.2f} %")
    print(f"  load-point deflection: PD {v * 1e6:.4f} um, beam theory {1e6 * (bend + shear):.4f} um (bending "
          f"{1e6 * bend:.4f} + shear {1e6 * shear:.4f}): {100 * dv:+.2f} %; stiffness P/v PD {P / v / 1e6:.3f} N/um, "
          f"beam {P / (bend + shear) / 1e6 / 1e6 * 1e6:.3f} N/um")
    bad = 0
    if a.curvature_bound is not None and abs(dk) > a.curvature_bound:
        print(f"FAIL: curvature off by {100 * dk:+.2f} % (bound {100 * a.curvature_bound:g} %)")
        bad = 1
    if a.deflection_bound is not None and abs(dv) > a.deflection_bound:
        print(f"FAIL: load-point deflection off by {100 * dv:+.2f} % (bound {100 * a.deflection_bound:g} %)")
        bad = 1
    if not bad:
        print("PASS")
    return bad


def damage(a):
    hist = history(a.csv)
    if a.out:  # scripts/plot_history's units: Applied_Displacement in m (plotted in mm), Reaction_* in N (kN)
        with open(a.out, "w") as f:
            f.write("time,step,Applied_Displacement,Reaction_Total_Y\n")
            for k, (t, v, p) in enumerate(hist):
                f.write(f"{t:g},{k},{v:.9g},{p:.9g}\n")
    ipk = max(range(len(hist)), key=lambda k: hist[k][2])
    measured = {"peak_load": hist[ipk][2], "peak_v": hist[ipk][1]}
    print(f"{a.exo}: {len(hist)} history rows; peak load {hist[ipk][2] / 1e3:.4f} kN at v = {hist[ipk][1] * 1e6:.3f} um "
          f"(t = {hist[ipk][0]:g}); last row v = {hist[-1][1] * 1e6:.3f} um, P = {hist[-1][2] / 1e3:.4f} kN")
    k0 = next((k for k in range(len(hist)) if hist[k][1] > 0), 1)
    print(f"  initial stiffness P/v = {hist[k0][2] / hist[k0][1] / 1e6:.4f} N/um (t = {hist[k0][0]:g})")
    measured["stiffness"] = hist[k0][2] / hist[k0][1]
    tip_lo, tip_up = g.LOWER[1], g.UPPER[1]
    first, first_upper = None, None
    n = nsteps(a.exo)
    for step in range(2, n + 1):
        t, rows = table(a.exo, step, ["Damage"])
        dam = [r for r in rows if r["Damage"] > 0]
        if not dam:
            continue
        # the upper flaw's tip zone: within 1.5 delta of its slot end in x, at most delta / 2 below it (the coarse deck
        # resolves no separate crack there: the first damage in this zone is the lower crack arriving)
        near_up = [r for r in dam if abs(r["X"] - tip_up[0]) < 1.5 * DELTA and tip_up[1] - 0.5 * DELTA <= r["Y"] < tip_up[1] + DELTA]
        lower = [r for r in dam if tip_lo[0] - DELTA < r["X"] < tip_up[0] + DELTA and r["Y"] < tip_up[1] - 0.5 * DELTA]
        if first is None:
            cx = sum(r["X"] for r in dam) / len(dam)
            cy = sum(r["Y"] for r in dam) / len(dam)
            top = max(dam, key=lambda r: r["Y"])
            first = (t, len(dam), cx, cy)
            measured["first_damage_t"] = t
            print(f"  first damage at t = {t:g} (v = {g.V_RATE * t * 1e6:g} um): {len(dam)} points, centroid "
                  f"({cx * 1e3:.2f}, {cy * 1e3:.2f}) mm; lower flaw tip ({tip_lo[0] * 1e3:g}, {tip_lo[1] * 1e3:g}) mm, "
                  f"upper flaw tip ({tip_up[0] * 1e3:g}, {tip_up[1] * 1e3:g}) mm")
        if near_up and first_upper is None:
            first_upper = t
            cx = sum(r["X"] for r in near_up) / len(near_up)
            cy = sum(r["Y"] for r in near_up) / len(near_up)
            top = max((r["Y"] for r in lower), default=float("nan"))
            print(f"  first damage in the upper flaw's tip zone (|x - {tip_up[0] * 1e3:g}| < 1.5 delta, y >= "
                  f"{(tip_up[1] - 0.5 * DELTA) * 1e3:g} mm) at t = {t:g}: {len(near_up)} points, centroid ({cx * 1e3:.2f}, "
                  f"{cy * 1e3:.2f}) mm; the highest damaged point below it then at y = {top * 1e3:.2f} mm")
        if step == n or step % 10 == 1:
            hi = max(dam, key=lambda r: r["Y"])
            print(f"  t = {t:g}: {len(dam)} damaged points, {sum(1 for r in dam if r['Damage'] >= 0.5)} with Damage >= 0.5, "
                  f"highest damaged point y = {hi['Y'] * 1e3:.2f} mm at x = {hi['X'] * 1e3:.2f} mm")
    bad = 0
    for e in a.expect or []:  # KEY=VALUE:RELTOL, a regression guard on a number the README reports
        key, rest = e.split("=")
        value, tol = map(float, rest.split(":"))
        got = measured.get(key, float("nan"))
        ok = abs(got - value) <= tol * abs(value)
        print(f"  {key}: {got:.6g} against {value:g} +- {100 * tol:g} %: {'ok' if ok else 'FAIL'}")
        bad += not ok
    if bad:
        return 1
    if a.expect_first_crack == "lower-right":
        ok = first is not None and first[2] > tip_lo[0] - DELTA and first[3] < g.H / 2 and \
            (first_upper is None or first_upper > first[0])
        if not ok:
            print("FAIL: the first damage is not at the right side of the lower flaw, or not before the upper flaw's")
            return 1
        print("PASS: the first damage is at the right side of the lower flaw" +
              ("" if first_upper is None else ", before the upper flaw's"))
    return 0


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("mode", choices=["elastic", "damage"])
    ap.add_argument("exo")
    ap.add_argument("csv")
    ap.add_argument("--curvature-bound", type=float)
    ap.add_argument("--deflection-bound", type=float)
    ap.add_argument("--out")
    ap.add_argument("--expect-first-crack", choices=["lower-right"])
    ap.add_argument("--expect", action="append",
                    help="KEY=VALUE:RELTOL (damage mode; keys peak_load [N], peak_v [m], stiffness [N/m], first_damage_t)")
    a = ap.parse_args()
    sys.exit(elastic(a) if a.mode == "elastic" else damage(a))
