#!/usr/bin/env python3
"""History and end state of a biaxial_test2_* run (make_biaxial.py): writes RUN_centre.csv (time, equivalent
strain, von Mises, mean stress, PIV at the specimen centre; the paper's Figs 17-18) and prints
  - the equivalent strain at the centre's first plastic step (paper: yield at 0.0011),
  - the centre's von Mises stress at the end against the analytic 232.6 kPa,
  - the spread of the end von Mises stress over all points, over the interior (at least 2 delta from every
    face) and over the boundary rows (band off: the surface effect of NOSB-PD).
Equivalent strain as the paper's PIV (Eq. 47): sqrt(1/2 e:e), e the deviator of the small strain sym(F) - I
with eps_zz = 0 (plane strain).

usage: biaxial_history.py RUN.csv RUN.e [--confining P] [--yield-bound R] [--centre-expect V --centre-bound R]
  --confining P       the deck's confining pressure [Pa] for the analytic end value (default 600e3, test 2)
  --yield-bound R     exit 1 unless the centre's yield estimate (where the lines through the last two elastic
                      and the first two plastic steps meet) is within R (relative) of the analytic 0.0011091
                      (make_biaxial.py: p_y / (2 (lambda + G)) per axis, sqrt(1/2 e:e))
  --centre-expect V   exit 1 unless the centre's end von Mises stress is within --centre-bound (relative) of V
  --all-bound R       exit 1 unless every point's end von Mises stress is within R (relative) of the analytic
                      value of the load the deck applies (the state is uniform when the band removes the surface
                      effect): with --follower the deck's Pressure is a follower load (a true -P on the deformed
                      faces, the analytic 232.6 kPa of test 2); without, a dead load on the reference area (a
                      nominal traction), so the true sigma_xx at the end is -P / F_yy, not -P (F_yy from the
                      centre probe)
  --follower          the deck's Pressure has 'Follower' = true (the band decks)
"""
import argparse
import csv
import math
import sys

import os
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

YIELD_EQ = 0.0011090795  # analytic yield equivalent strain of the confinement (make_biaxial.py)
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from make_biaxial import analytic_end  # noqa: E402  the uniform end state: sigma_xx = -P, s_zz = 0, f = 0 (Eq. 38)


def eq_strain(fxx, fyy, fxy, fyx):
    e = [fxx - 1, fyy - 1, 0.0]
    exy = 0.5 * (fxy + fyx)
    m = sum(e) / 3
    d = [v - m for v in e]
    return math.sqrt(0.5 * (sum(v * v for v in d) + 2 * exy * exy))


def main(args):
    csv_path, exo_path = args.csv, args.exo
    ANALYTIC = analytic_end(args.confining)
    rows = list(csv.DictReader(open(csv_path)))
    out = csv_path[:-4] + "_centre.csv"
    yield_eq, last_elastic, hist = None, 0.0, []
    with open(out, "w") as f:
        f.write("time,equivalent_strain,von_mises,mean_stress,equivalent_plastic_strain\n")
        for r in rows:
            g = lambda n: float(r["Probe_Centre_" + n])
            eq = eq_strain(g("Deformation_GradientXX"), g("Deformation_GradientYY"), g("Deformation_GradientXY"),
                           g("Deformation_GradientYX"))
            hist.append((eq, g("Von_Mises_Stress"), g("Equivalent_Plastic_Strain") > 0))
            if yield_eq is None and g("Equivalent_Plastic_Strain") > 0:
                yield_eq = eq
            elif yield_eq is None:
                last_elastic = eq
            f.write(f"{r['time']},{eq:.10g},{g('Von_Mises_Stress'):.10g},{g('Mean_Stress'):.10g},"
                    f"{g('Equivalent_Plastic_Strain'):.10g}\n")
    end = float(rows[-1]["Probe_Centre_Von_Mises_Stress"])
    # P_xx = J sigma_xx F^-T_xx = F_yy sigma_xx in plane strain: the dead load's true confinement at the end.
    fyy = float(rows[-1]["Probe_Centre_Deformation_GradientYY"])
    DEAD = analytic_end(args.confining / fyy)
    print(f"{out}: {len(rows)} rows")
    # The load steps locate yield only between the last elastic and the first plastic step (7 % apart here);
    # the estimate is where the von Mises-strain line of the last two elastic steps meets that of the next
    # two plastic ones (the confinement's two branches are straight lines, make_biaxial.py).
    k = next(i for i, h in enumerate(hist) if h[2])
    (a0, b0), (a1, b1), (c0, d0), (c1, d1) = [h[:2] for h in hist[k - 2:k + 2]]
    s_el, s_pl = (b1 - b0) / (a1 - a0), (d1 - d0) / (c1 - c0)
    estimate = (d0 - b0 + s_el * a0 - s_pl * c0) / (s_el - s_pl)
    print(f"centre: yield estimate (elastic and plastic branches' intersection) at equivalent strain {estimate:.6f} "
          f"({100 * (estimate / YIELD_EQ - 1):+.2f} % of the analytic)")
    print(f"centre: yields between equivalent strains {last_elastic:.6f} (last elastic step) and {yield_eq:.6f} "
          f"(first plastic step): {100 * (last_elastic / YIELD_EQ - 1):+.1f} % .. {100 * (yield_eq / YIELD_EQ - 1):+.1f} % "
          f"of the analytic {YIELD_EQ:.6f} (paper 0.0011)")
    print(f"centre: end von Mises {end / 1e3:.2f} kPa, analytic {ANALYTIC / 1e3:.2f} kPa ({100 * (end / ANALYTIC - 1):+.2f} %)")
    table = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "exodus_to_csv"), exo_path, "--vars",
                            "Von_Mises_Stress"], check=True, capture_output=True, text=True).stdout.splitlines()
    pts = [tuple(float(v) for v in line.split(",")) for line in table[2:]]
    x = [p[1] for p in pts]
    y = [p[2] for p in pts]
    vm = [p[4] for p in pts]
    dx = min(abs(a - b) for a, b in zip(sorted(set(x))[1:], sorted(set(x))[:-1]))
    two_delta = 2 * 3.015 * dx
    inner = [v for v, a, b in zip(vm, x, y) if min(a - min(x), max(x) - a, b - min(y), max(y) - b) >= two_delta]
    outer = [v for v, a, b in zip(vm, x, y) if min(a - min(x), max(x) - a, b - min(y), max(y) - b) < two_delta]
    pct = lambda v: 100 * (v / ANALYTIC - 1)
    for label, vals in (("all points", list(vm)), ("interior (>= 2 delta from the faces)", inner),
                        ("within 2 delta of a face", outer)):
        if vals:
            print(f"end von Mises, {label} ({len(vals)}): min {min(vals) / 1e3:.2f} ({pct(min(vals)):+.2f} %), "
                  f"max {max(vals) / 1e3:.2f} kPa ({pct(max(vals)):+.2f} %)")
    print(f"analytic end von Mises for the deck's dead-load pressure (true sigma_xx = -P / F_yy = "
          f"{-args.confining / fyy / 1e3:.2f} kPa): {DEAD / 1e3:.2f} kPa; all points: min {100 * (min(vm) / DEAD - 1):+.2f} %, "
          f"max {100 * (max(vm) / DEAD - 1):+.2f} %")
    ok = True
    ref = ANALYTIC if args.follower else DEAD
    if args.all_bound is not None and max(abs(min(vm) / ref - 1), abs(max(vm) / ref - 1)) > args.all_bound:
        print(f"FAIL: end von Mises not within {100 * args.all_bound:g} % of {ref:.6g} at every point")
        ok = False
    if args.yield_bound is not None and abs(estimate / YIELD_EQ - 1) > args.yield_bound:
        print(f"FAIL: the centre's yield estimate {estimate:.6f} is not within {100 * args.yield_bound:g} % of {YIELD_EQ:.6f}")
        ok = False
    if args.centre_expect is not None and abs(end / args.centre_expect - 1) > args.centre_bound:
        print(f"FAIL: centre end von Mises {end:.6g} not within {100 * args.centre_bound:g} % of {args.centre_expect:.6g}")
        ok = False
    return 0 if ok else 1


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("exo")
    ap.add_argument("--confining", type=float, default=600e3, help="confining pressure [Pa] (test 2: 600e3)")
    ap.add_argument("--yield-bound", type=float)
    ap.add_argument("--centre-expect", type=float)
    ap.add_argument("--centre-bound", type=float, default=0.01)
    ap.add_argument("--all-bound", type=float)
    ap.add_argument("--follower", action="store_true")
    sys.exit(main(ap.parse_args()))
