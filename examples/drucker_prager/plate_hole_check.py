#!/usr/bin/env python3
"""History of a plate_hole_* run (make_plate_hole.py) at the paper's three monitoring points (Li & Geng, seed 003,
Sec. 5.3.2, Fig. 21), against the elastic finite-element reference (plate_hole_ccx.py ->
plate_hole_fe_reference.csv, stress per metre of imposed displacement of one edge).

Writes RUN_P1.csv, RUN_P2.csv, RUN_P3.csv (u, equivalent strain sqrt(1/2 e:e) of the point's small strain with
eps_zz = 0 (plane strain; the paper's PIV, Eq. 47), von Mises, mean stress, equivalent plastic strain): the paper's
Fig. 21 (a) (xi against u) and (b) (von Mises against equivalent strain); plot them with scripts/plot_history.

Prints
  - the elastic step (the first load step, u = 1 um): each point's stress against the FE reference;
  - the displacement u (of one edge) at which each point reaches the Drucker-Prager yield surface, f = J - m0 (A I + B)
    = 0 (compression-positive invariants I = -tr sigma, J = sqrt(1/2 s:s), materials/DruckerPragerPlasticity.hpp),
    predicted from the FE elastic stress (linear in u: u_y = m0 B / (J1 - m0 A I1), J1 and I1 per metre of u) and
    from the run's own first step, against the run's bracket (last elastic step, first plastic step);
  - P2's equivalent plastic strain at the end.

usage: plate_hole_check.py RUN.csv [--exo RUN.e] [--paper-onset U] [--elastic-bound R [--elastic-points P1,P2,P3]] [--onset-bound R]
                                   [--onset-self] [--p2-elastic] [--order]
  --elastic-bound R  exit 1 unless at P1 and P3 sigma_yy, and at P2 sigma_xx (each point's dominant component) of the
                     first step is within R (relative) of the FE value (only at the points of --elastic-points)
  --onset-bound R    exit 1 unless P1's first plastic step's u is within R (relative) of the FE-predicted onset
                     and P1 is elastic at the step before it
  --onset-self       exit 1 unless P1 (the first point to yield: elastic and proportional until then) yields in the
                     load step that contains the onset predicted from the run's own first step
  --p2-elastic       exit 1 unless P2 ends with zero equivalent plastic strain
  --order            exit 1 unless P1 yields before P3
"""
import argparse
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from make_plate_hole import C, M0, PHI  # noqa: E402

S = math.sin(math.radians(PHI))
A = 2 * S / (math.sqrt(3) * (3 - S))                                    # Eq. 38
B = 6 * C * math.cos(math.radians(PHI)) / (math.sqrt(3) * (3 - S))
POINTS = ("P1", "P2", "P3")
DOMINANT = {"P1": "YY", "P2": "XX", "P3": "YY"}


def invariants(sxx, syy, szz, sxy):
    """Compression-positive I = -tr sigma and J = sqrt(1/2 s:s)."""
    m = (sxx + syy + szz) / 3
    return -3 * m, math.sqrt(0.5 * ((sxx - m) ** 2 + (syy - m) ** 2 + (szz - m) ** 2 + 2 * sxy * sxy))


def onset(sxx, syy, szz, sxy, u):
    """u at which the linear elastic state (stress at u) reaches f = 0 with m = m0."""
    I, J = invariants(sxx, syy, szz, sxy)
    d = J - M0 * A * I
    return u * M0 * B / d if d > 0 else math.inf


def eq_strain(fxx, fyy, fxy, fyx):
    e = [fxx - 1, fyy - 1, 0.0]
    exy = 0.5 * (fxy + fyx)
    m = sum(e) / 3
    return math.sqrt(0.5 * (sum((v - m) ** 2 for v in e) + 2 * exy * exy))


def main(a):
    rows = list(csv.DictReader(open(a.csv)))
    ref = {r["point"]: r for r in csv.DictReader(open(os.path.join(HERE, a.reference)))}
    g = lambda r, p, v: float(r[f"Probe_{p}_{v}"])
    u = [float(r["Applied_Displacement"]) for r in rows]
    print(f"{a.csv}: {len(rows)} rows, u (one edge) to {u[-1] * 1e3:.4g} mm")
    ok = True
    # elastic step: the first row with u > 0
    k1 = next(i for i, v in enumerate(u) if v > 0)
    u1 = u[k1]
    print(f"elastic step (u = {u1 * 1e3:.4g} mm), PD against the FE reference (plate_hole_fe_reference.csv):")
    for p in POINTS:
        pd = {c: g(rows[k1], p, "Unrotated_Cauchy_Stress" + c) for c in ("XX", "YY", "ZZ", "XY")}
        fe = {c: float(ref[p][f"s{c.lower()}_per_m"]) * u1 for c in ("XX", "YY", "ZZ", "XY")}
        kir = {c: float(ref[p][f"kirsch_s{c.lower()}_per_m"]) * u1 for c in ("XX", "YY", "XY")}
        rel = pd[DOMINANT[p]] / fe[DOMINANT[p]] - 1
        print(f"  {p}: sxx {pd['XX']:9.2f} (FE {fe['XX']:9.2f}, Kirsch {kir['XX']:9.2f})  syy {pd['YY']:9.2f} "
              f"(FE {fe['YY']:9.2f}, Kirsch {kir['YY']:9.2f})  szz {pd['ZZ']:8.2f} (FE {fe['ZZ']:8.2f})  sxy {pd['XY']:8.2f} "
              f"(FE {fe['XY']:8.2f}) Pa;  s{DOMINANT[p].lower()} {100 * rel:+.1f} % of FE")
        if a.elastic_bound is not None and p in a.elastic_points.split(",") and abs(rel) > a.elastic_bound:
            print(f"FAIL: {p} s{DOMINANT[p].lower()} {100 * rel:+.1f} % off FE (bound {100 * a.elastic_bound:g} %)")
            ok = False
    p2 = {c: g(rows[k1], "P2", "Unrotated_Cauchy_Stress" + c) for c in ("XX", "YY")}
    lin = max(abs(g(r, p, "Unrotated_Cauchy_Stress" + DOMINANT[p]) / v / (g(rows[k1], p, "Unrotated_Cauchy_Stress" + DOMINANT[p]) / u1) - 1)
              for p in POINTS for r, v in zip(rows, u) if v > 0 and g(r, p, "Equivalent_Plastic_Strain") == 0
              and all(g(r, q, "Equivalent_Plastic_Strain") == 0 for q in POINTS))
    print(f"  P2's sigma_yy / sigma_xx (0 at a free surface with normal y): {100 * p2['YY'] / p2['XX']:.1f} %; dominant stress per "
          f"unit u over the steps before any point yields: within {lin:.1e} of the first step's")
    print(f"yield onset, u of one edge (m0 {M0:g}, A {A:.5f}, B {B:.1f} Pa; f = J - m0 (A I + B)):")
    first = {}
    for p in POINTS:
        fe_on = onset(*(float(ref[p][f"s{c}_per_m"]) for c in ("xx", "yy", "zz", "xy")), 1.0)
        pd_on = onset(*(g(rows[k1], p, "Unrotated_Cauchy_Stress" + c) for c in ("XX", "YY", "ZZ", "XY")), u1)
        kp = next((i for i, r in enumerate(rows) if g(r, p, "Equivalent_Plastic_Strain") > 0), None)
        first[p] = kp
        br = (f"run: elastic to u = {u[kp - 1] * 1e3:.4g} mm, plastic from {u[kp] * 1e3:.4g} mm" if kp is not None
              else f"run: elastic to the end (u = {u[-1] * 1e3:.4g} mm)")
        if kp is not None:
            br += f" (von Mises there {g(rows[kp], p, 'Von_Mises_Stress') / 1e3:.3f} kPa)"
        print(f"  {p}: FE-predicted {fe_on * 1e3:.5g} mm; from the run's elastic step {pd_on * 1e3:.5g} mm; {br}")
        if p == "P1" and a.paper_onset:
            # m0 with which the FE stress reaches f = 0 at the paper's onset: m0 (B + u A I1) = u J1
            I1, J1 = invariants(*(float(ref[p][f"s{c}_per_m"]) for c in ("xx", "yy", "zz", "xy")))
            for lab, uu in (("per edge", a.paper_onset), ("as the total shortening", a.paper_onset / 2)):
                print(f"      m0 that puts P1's FE onset at the paper's {a.paper_onset * 1e3:g} mm {lab}: "
                      f"{uu * J1 / (B + uu * A * I1):.4f}")
        if p == "P1" and a.onset_self and (kp is None or not u[kp - 1] < pd_on <= u[kp] * (1 + 1e-9)):
            print(f"FAIL: P1 does not yield in the step containing its own elastic prediction {pd_on * 1e3:.5g} mm")
            ok = False
        if p == "P1" and a.onset_bound is not None:
            if kp is None or abs(u[kp] / fe_on - 1) > a.onset_bound or u[kp - 1] >= fe_on * (1 + a.onset_bound):
                print(f"FAIL: P1's onset not within {100 * a.onset_bound:g} % of the FE prediction {fe_on * 1e3:.5g} mm")
                ok = False
    # far from the hole: uniaxial plane strain, sigma_xx = 0, sigma_zz = nu sigma_yy, sigma_yy = -E' 2u / L
    from make_plate_hole import E, NU
    s1 = -E / (1 - NU * NU) * 2 / a.side
    print(f"  far field (no hole, sigma_xx = 0): {onset(0.0, s1, NU * s1, 0.0, 1.0) * 1e3:.5g} mm")
    if a.exo:
        import netCDF4
        import numpy as np
        d = netCDF4.Dataset(a.exo)
        names = ["".join(c.decode() for c in n if c) for n in d.variables["name_elem_var"][:].data]
        v = d.variables["vals_elem_var%deb1" % (names.index("Equivalent_Plastic_Strain") + 1)][:]
        x, y, t = d.variables["coordx"][:], d.variables["coordy"][:], d.variables["time_whole"][:]
        first = next((i for i in range(v.shape[0]) if (v[i] > 0).any()), None)
        if first is not None:
            pts = ", ".join(f"({x[j] * 1e3:g}, {y[j] * 1e3:g})" for j in np.where(v[first] > 0)[0][:8])
            print(f"  first plastic points (output step {first}, u = {u[first] * 1e3:.4g} mm): {pts} mm")
        # the hole's edge in the first step: the points within 2 dx of the circle, in angle order (125..160 deg,
        # the upper-left staircase): the band's growing mode shows as a point-to-point oscillation there
        xs = np.unique(np.round(x, 9))
        dxl = float(np.min(np.diff(xs)))
        cx, cy = (x.max() + x.min()) / 2, (y.max() + y.min()) / 2
        rr, th = np.hypot(x - cx, y - cy), np.degrees(np.arctan2(y - cy, x - cx))
        sxx = d.variables["vals_elem_var%deb1" % (names.index("Unrotated_Cauchy_StressXX") + 1)][1]
        sel = np.where((rr < 5e-3 + 2 * dxl) & (th > 125) & (th <= 160))[0]
        sel = sel[np.argsort(th[sel])]
        print(f"  hole edge (r < R + 2 dx), 125..160 deg, first step: sigma_xx {' '.join('%.0f' % sxx[j] for j in sel)} Pa "
              f"({len(sel)} points, {float(sxx[sel].min()):.0f} .. {float(sxx[sel].max()):.0f} Pa)")
        for i in range(1, v.shape[0]):
            if i == v.shape[0] - 1 or i % 10 == 0:
                print(f"  plastic points at u = {u[i] * 1e3:.4g} mm: {int((v[i] > 0).sum())} of {v.shape[1]}")
    xi2 = g(rows[-1], "P2", "Equivalent_Plastic_Strain")
    print(f"  P2 equivalent plastic strain at the end: {xi2:.3g}")
    for p in POINTS:
        print(f"  {p} at the end: equivalent plastic strain {g(rows[-1], p, 'Equivalent_Plastic_Strain'):.4g}, "
              f"von Mises {g(rows[-1], p, 'Von_Mises_Stress') / 1e3:.3f} kPa, mean {g(rows[-1], p, 'Mean_Stress') / 1e3:.3f} kPa")
    if a.p2_elastic and xi2 > 0:
        print("FAIL: P2 yielded")
        ok = False
    if a.order and not (first["P1"] is not None and (first["P3"] is None or first["P1"] < first["P3"])):
        print("FAIL: P1 does not yield before P3")
        ok = False
    for p in POINTS:
        out = f"{a.csv[:-4]}_{p}.csv"
        with open(out, "w") as f:
            f.write("applied_displacement,equivalent_strain,von_mises,mean_stress,equivalent_plastic_strain\n")
            for r, v in zip(rows, u):
                eq = eq_strain(*(g(r, p, "Deformation_Gradient" + c) for c in ("XX", "YY", "XY", "YX")))
                f.write(f"{v:.10g},{eq:.10g},{g(r, p, 'Von_Mises_Stress'):.10g},{g(r, p, 'Mean_Stress'):.10g},"
                        f"{g(r, p, 'Equivalent_Plastic_Strain'):.10g}\n")
    print(f"wrote {a.csv[:-4]}_P{{1,2,3}}.csv")
    return 0 if ok else 1


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--side", type=float, default=0.1, help="the plate's side [m] (far-field onset)")
    ap.add_argument("--reference", default="plate_hole_fe_reference.csv", help="FE reference in this directory "
                    "(plate_hole_fe_reference_w40.csv for the plate_hole_w40_* decks)")
    ap.add_argument("--exo", help="the run's .e: the first plastic points and the plastic count")
    ap.add_argument("--elastic-bound", type=float)
    ap.add_argument("--elastic-points", default="P1,P2,P3")
    ap.add_argument("--onset-bound", type=float)
    ap.add_argument("--onset-self", action="store_true")
    ap.add_argument("--paper-onset", type=float, help="the paper's onset at point 1 [m] (0.011e-3): prints the m0 that "
                    "puts the FE onset there")
    ap.add_argument("--p2-elastic", action="store_true")
    ap.add_argument("--order", action="store_true")
    sys.exit(main(ap.parse_args()))
